O0075 (G75 grooving: an 8 mm groove with a 4 mm tool, two plunges)
T0101
G99 G97 S600 M03
G00 X44.0 Z-10.0
G75 R0.5
G75 X30.0 Z-14.0 P4000 Q4000 F0.05
G00 X100.0 Z50.0
M30
