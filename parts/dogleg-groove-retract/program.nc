O0011 (a groove, then a retract that crashes as the machine moves it)
G99 G97 S500 M03 T0101
G00 X44. Z-23.
G01 X30. F0.1
G00 X44.
G00 Z-24.
G01 X30.
G00 X200. Z-22.
M30
