behavior_name=goto_list
# Written by SFMC on UTC: 2026-11-20T09:14:03.511207
# goto_l11.ma

<start:b_arg>
	b_arg: num_legs_to_run(nodim) -1
	b_arg: start_when(enum) 0 # BAW_IMMEDIATELY
	b_arg: list_stop_when(enum) 7 # BAW_WHEN_WPT_DIST
	b_arg: list_when_wpt_dist(m) 100.0
	b_arg: initial_wpt(enum) -1 # One after last achieved
	b_arg: num_waypoints(nodim) 5
<end:b_arg>
<start:waypoints>
-7040.12	4121.50
-7035.8	4118.25
-7031.44	4115.0
-7027.1	4111.75
-7022.76	4108.5
<end:waypoints>
