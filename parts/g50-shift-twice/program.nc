O0050 (G50: the frame moves, not the tool; one subprogram cuts in two places)
G28 U0. W0.
G50 X100. Z50.
G99 G97 S800 M03 T0101
G00 X44. Z-10.
M98 P0200
M01
G50 W30.
G00 Z-10.
M98 P0200
G00 X100. Z50.
M30
O0200 (a 3 mm groove 2 deep, from X44)
G01 U-8. F0.05
G00 U8.
M99
