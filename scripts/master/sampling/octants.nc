(METHOD SAMPLING)
(Lines in all eight octants by sampling: out from X60 Y60 and back, 30 mm along one axis and 11 mm)
(along the other, so each pair of lines covers two opposite octants; every reversal is a stop)
G21 G90
G00 X60 Y60
G01 X90 Y71 F750     (octant 1)
G01 X60 Y60          (octant 5)
G01 X71 Y90          (octant 2)
G01 X60 Y60          (octant 6)
G01 X49 Y90          (octant 3)
G01 X60 Y60          (octant 7)
G01 X30 Y71          (octant 4)
G01 X60 Y60          (octant 8)
G01 X30 Y49          (octant 5)
G01 X60 Y60
G01 X49 Y30          (octant 6)
G01 X60 Y60
G01 X71 Y30          (octant 7)
G01 X60 Y60
G01 X90 Y49          (octant 8)
G01 X60 Y60
