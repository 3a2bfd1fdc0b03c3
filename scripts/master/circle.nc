%
(A full circle of radius 20 mm about X50 Y50, counter-clockwise, from its right-hand point)
N10 G21 G90
N20 G00 X70 Y50
N30 G03 X70 Y50 I-20 J0 F750
%
