(expect: 9:1: error: G71 contour goes past the start point before its last block)
(control: haas; a Haas lathe)
(dialect: haas; its one-block cycles)
G00 X52. Z2.
G71 P10 Q20 U0.5 W0.1 D2. F0.25
N10 G00 X30.
G01 Z-20.
X50. Z-30.
X55.
N20 Z-35.
