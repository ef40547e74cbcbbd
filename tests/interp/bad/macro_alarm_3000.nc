(expect: 4:21: error: the program raises alarm 3001 with #3000 = 1: TOO BIG)
#1 = 120
G00 X50 Z2
IF [#1 GT 100] THEN #3000 = 1 (TOO BIG)
G01 X#1 F0.2
M30
