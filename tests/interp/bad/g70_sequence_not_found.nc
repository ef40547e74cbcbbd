(expect: 3:9: error: G70 Q40: there is no block N40 in this program)
G00 X60 Z2 F0.2
G70 P10 Q40
M30
N10 G00 X20
N20 G01 Z-10
