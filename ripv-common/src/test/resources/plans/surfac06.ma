behavior_name=surface
# climb to surface, pitch servoed
# Hand Written
<start:b_arg>
b_arg: start_when(enum) 9 # 9-every when_secs
b_arg: end_action(enum) 1 # 0-quit, 1 wait for ^C quit/resume, 2 resume
b_arg: when_secs(s) 10800 # How long between surfacing
b_arg: gps_wait_time(s) 300 # how long to wait for gps
b_arg: keystroke_wait_time(sec) 300 # how long to wait for control-C
b_arg: c_use_pitch(enum) 3 # 3:servo
b_arg: c_pitch_value(X) 0.4528 # 26 deg
b_arg: printout_cycle_time(sec) 60.0 # How often to print dialog
<end:b_arg>
