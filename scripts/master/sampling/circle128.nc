(METHOD SAMPLING)
(A full circle of R 51.2 mm = 1024 steps at C_R 3, eps_A = 1 step. The chords that run along an)
(axis are 128 steps of it, eq. 5's whole segment, and the next chord's set-up ahead of the join)
(waited for a last segment that came only with the chord's last sample; it then ran in one piece)
(after it, to the 8155 timer's terminal count, and the board stopped in the monitor at 6.384 s)
G21 G90
G00 X111.2 Y60
G03 X111.2 Y60 I-51.2 J0 F750
