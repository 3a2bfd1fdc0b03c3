(METHOD SAMPLING)
(RAMP OFF)
(The same line without the ramp: 500 steps/s from the first sample, above the start-stop limit)
G21 G90
G01 X100 F1500
