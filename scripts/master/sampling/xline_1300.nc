(METHOD SAMPLING)
(100 mm along X at 1300 mm/min with the ramp: 433 steps/s on one motor, section 5.3's "up to 1300 mm/min")
G21 G90
G01 X100 F1300
