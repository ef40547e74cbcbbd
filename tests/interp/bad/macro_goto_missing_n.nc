(expect: 4:19: error: GOTO 30: there is no block N30 in this program)
G00 X50 Z2
#1 = 3
IF [#1 GT 2] GOTO 30
G01 U-2 F0.1
N20 M30
