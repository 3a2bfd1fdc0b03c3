(Arcs in all four quadrants and both directions: a circle of R 15 mm about X60 Y60 in four)
(counter-clockwise quarters, then back in four clockwise quarters, centres by I J)
G21 G90
G00 X75 Y60
G03 X60 Y75 I-15 J0 F600   ; quadrant 1
G03 X45 Y60 I0 J-15        ; quadrant 2
G03 X60 Y45 I15 J0         ; quadrant 3
G03 X75 Y60 I0 J15         ; quadrant 4
G02 X60 Y45 I-15 J0        ; quadrant 4, clockwise
G02 X45 Y60 I0 J15
G02 X60 Y75 I15 J0
G02 X75 Y60 I0 J-15
