(expect: 2:5: error: G00 and G01 are both motion)
G00 G01 X20 F0.1;
