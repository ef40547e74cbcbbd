(expect: 3:19: error: R12 and U-20 have opposite signs and |R| > |U/2|)
G00 X60 Z2;
G90 X40 Z-20 F0.1 R12;
