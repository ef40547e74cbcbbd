(two-start thread, lead 4 pitch 2, with G92 L2: a relief at Z-30...-35.5, then four radial passes, each cutting both starts)
G99 M03 S500
T0202
G00 X32 Z-35.5
G01 X27 F0.05
G00 X32
W2.5
G01 X27
G00 X32
Z5
T0101
G92 X29 Z-33 F4 L2
X28.4
X27.8
X27.546
G00 X40 Z20
M30
