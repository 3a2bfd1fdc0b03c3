(METHOD SAMPLING)
(A 100 mm line along X at 1200 mm/min, 400 steps/s on one motor, with the ramp)
G21 G90
G01 X100 F1200
