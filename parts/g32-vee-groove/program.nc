(A relief at Z-30...-40, then one G32 pass of a sharp 60 degree V, lead 2, started at 90 degrees)
G99 M03 S500
G00 X32 Z-30
G01 X26 F0.1
Z-40
G00 X32
Z4
X28
G32 Z-35 F2 Q90000
G00 X32
Z4
X40 Z20
M30
