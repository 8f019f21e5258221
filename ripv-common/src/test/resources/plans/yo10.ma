behavior_name=yo
# yo10.ma: 3 to 30 m
<start:b_arg>
    b_arg: start_when(enum)             2   # pitch idle
    b_arg: num_half_cycles_to_do(nodim) -1  # forever
    b_arg: d_target_depth(m)            30
    b_arg: d_target_altitude(m)         5
    b_arg: c_dive_bpump_value(X)        -260.0
    b_arg: c_climb_bpump_value(X)       1000.0
    b_arg: d_use_pitch(enum)            3
    b_arg: d_pitch_value(X)             -0.4538 # -26 deg
    b_arg: c_climb_target_depth(m)      3
    b_arg: end_action(enum)             2   # resume
<end:b_arg>
