(expect: 3:1: error: G94 needs X)
G00 X100 Z2;
G94 X20 F0.1;
