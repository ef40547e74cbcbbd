(expect: 2:11: error: P12 selects a spindle)
G97 S1200 P12 M03
M30
