behavior_name=goto_list
#  hand written, ru29 box off Martha's Vineyard
#  2026-11-21 alice: moved wpt 2 north of the shoal
#  2026-11-22 bob: dropped the old start point
<start:b_arg>
b_arg: start_when(enum)       0     # BAW_IMMEDIATELY
b_arg: list_stop_when(enum)   7 # BAW_WHEN_WPT_DIST
b_arg:  list_when_wpt_dist(m)	50  # used if list_stop_when == 7
b_arg: initial_wpt(enum)     -2# closest
                                 # >=0: start with this waypoint,
                                 # -1 the one after the last achieved
	b_arg: num_waypoints(nodim)	3
b_arg: num_legs_to_run(nodim) -1 # loop
<end:b_arg>
<start:waypoints>
# LON        LAT
#-7045.000  4115.000   old start, too close to the shoal
-7042.500	4117.250  # wpt 0 west corner
  -7038.000   4119.900 #wpt 1 north of the shoal
-7036.250 4116.125
<end:waypoints>

# trailing notes are comments too
