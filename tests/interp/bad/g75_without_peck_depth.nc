(expect: 3:1: error: the depth of each peck along X)
G00 X42 Z-10
G75 X30 Z-14 Q4000 F0.05
