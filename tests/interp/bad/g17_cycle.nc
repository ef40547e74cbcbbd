(expect: 3:5: error: this machine has no Y axis)
G00 X60 Z2;
G17 G94 X20 Z-5 F0.1;
