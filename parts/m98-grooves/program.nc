O0098 (three grooves: one subprogram called three times)
T0101
G99 G97 S600 M03
G00 X44.0 Z-10.0
M98 P30200
G00 X100.0 Z50.0
M30
O0200 (a 3 mm groove to X32, then 10 mm toward the chuck)
G01 X32.0 F0.05
G00 X44.0
W-10.0
M99
