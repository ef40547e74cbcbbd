(G02/G03 by R, by R < 0, by I/K, modal, and a full circle; arcs.csv is worked out by hand)
G00 X20 Z0
G01 Z-2 F0.2
G02 X20 Z-10 R5
G03 W-8 R-5
U10 W-5 I5 K0
G02 I-5 K0
G00 X200 Z200
