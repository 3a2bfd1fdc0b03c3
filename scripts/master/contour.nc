(A contour mixing lines and arcs, with a Z plunge and a retract; part in inches, part incremental)
G21 G90
G00 X10 Y10
G01 Z2 F300          (plunge: Z moves on its own)
G01 X50 Y10 F750
G02 X70 Y30 I0 J20   (clockwise, centre by I J)
G91 G01 X0 Y20       (incremental)
G90 G03 X40 Y80 R30  (counter-clockwise, by R, the long way is R-30)
G20 G01 X0.7874 Y1.9685 (inches: 20 mm, 50 mm)
G21 G02 X10 Y10 R-25 (clockwise the long way round)
G00 Z0               (retract)
