(METHOD SAMPLING)
(RAMP OFF)
(The same 100 mm diagonal at 1500 mm/min without the ramp: full feed from the first sample)
G21 G90
G01 X70.711 Y70.711 F1500
