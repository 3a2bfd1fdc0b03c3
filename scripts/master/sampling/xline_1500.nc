(METHOD SAMPLING)
(100 mm along X at 1500 mm/min with the ramp: 500 steps/s on one motor; each pulse placed where x* crosses its step)
G21 G90
G01 X100 F1500
