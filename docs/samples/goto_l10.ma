behavior_name=goto_list
# goto_l10.ma: a Slocum waypoint list, the file ru29-new-mission.wf sends (docs/workflows.md).
# Four waypoints off Woods Hole (lon lat as DDMM.MMM), then back to the first, for ever.

<start:b_arg>
    b_arg: start_when(enum)         0    # BAW_IMMEDIATELY
    b_arg: num_legs_to_run(nodim)  -1    # loop
    b_arg: list_stop_when(enum)     7    # BAW_WHEN_WPT_DIST
    b_arg: initial_wpt(enum)       -2    # the closest
    b_arg: num_waypoints(nodim)     4
<end:b_arg>

<start:waypoints>
-7032.188 4137.994
-7030.000 4136.000
-7028.000 4138.000
-7030.000 4140.000
<end:waypoints>
