(M30 x 2 x 30: a relief at Z-30...-35.5 cut with a 3 mm grooving blade in two overlapping plunges, then G76 with a sharp 60 degree tool)
G99 M03 S500
T0202
G00 X32 Z-35.5
G01 X27 F0.05
G00 X32
W2.5
G01 X27
G00 X32
Z5
T0101
G76 P020060 Q100 R0.05
G76 X27.546 Z-33 P1227 Q400 F2
G00 X40 Z20
M30
