(A rectangle 60 x 40 mm with corners of radius 8 mm, lower left corner at X20 Y20, counter-clockwise)
N1 G21 G90
N2 G00 X28 Y20
N3 G01 X72 F750
N4 G03 X80 Y28 R8
N5 G01 Y52
N6 G03 X72 Y60 R8
N7 G01 X28
N8 G03 X20 Y52 R8
N9 G01 Y28
N10 G03 X28 Y20 R8
