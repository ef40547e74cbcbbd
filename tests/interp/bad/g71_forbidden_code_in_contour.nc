(expect: 5:5: error: G90 is not allowed in the contour of G71)
G00 X60 Z2
G71 P10 Q20 U0.5 F0.2
N10 G00 X20
N20 G90 X30 Z-10
M30
