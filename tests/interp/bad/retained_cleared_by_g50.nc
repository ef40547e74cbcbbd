(expect: 5:1: error: the end point's Z)
G00 X60 Z2;
G94 X50 Z-5 F0.2;
G50 X60 Z2;
X40;
