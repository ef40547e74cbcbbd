(expect: 4:1: error: the program makes more than 2000000 moves)
G00 X0 Z2
G74 R1
G74 Z-1000000000000 Q1 F0.1
M30
