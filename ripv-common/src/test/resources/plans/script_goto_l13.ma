behavior_name=goto_list

#
<start:b_arg>
b_arg: num_legs_to_run(nodim) -2
b_arg: start_when(enum) 0 # BAW_IMMEDIATELY
b_arg: list_stop_when(enum) 7 # BAW_WHEN_WPT_DIST
b_arg: initial_wpt(enum) 0 # closest
b_arg: num_waypoints(nodim) 4
<end:b_arg>
<start:waypoints>
-7032.1880	4137.9940
-7030.0000	4136.0000
-7028.0000	4138.0000
-7030.0000	4140.0000
<end:waypoints>

