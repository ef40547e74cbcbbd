(expect: 8:5: error: M98 calls O0001 while it is already running)
O0001
G00 X50 Z2
M98 P2
M30
O0002
G01 U-2 F0.1
M98 P1
M99
