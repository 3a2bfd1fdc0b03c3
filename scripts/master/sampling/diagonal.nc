(METHOD SAMPLING)
(The feed test: a 100 mm diagonal at 1500 mm/min, from standstill to standstill, with the ramp)
G21 G90
G01 X70.711 Y70.711 F1500
