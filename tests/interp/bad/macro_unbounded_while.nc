(expect: 3:1: error: the program is still in this loop after 1000000 blocks run again)
G00 X50 Z2
WHILE [#1 LT 10] DO 1
#2 = #2 + 1
END 1
M30
