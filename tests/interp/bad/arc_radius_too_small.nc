(expect: 3:23: error: R4 is too small: the end point is 10 mm from the start)
G00 X30 Z1;
G01 Z0 F0.1; G02 Z-10 R4;
