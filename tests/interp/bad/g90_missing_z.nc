(expect: 3:1: error: G90 needs X)
G00 X100 Z2;
G90 X20 F0.1;
