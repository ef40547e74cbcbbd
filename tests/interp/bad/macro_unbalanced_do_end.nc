(expect: 4:1: error: DO 1 has no END 1 before the end of its program)
G00 X50 Z2
#1 = 0
WHILE [#1 LT 3] DO 1
G01 U-1 F0.1
#1 = #1 + 1
M30
