(METHOD SAMPLING)
(RAMP OFF)
(The same line without the ramp: its first pulses come 2 ms apart, 500 steps/s, above the start-stop limit)
G21 G90
G01 X100 F1200
