(expect: 3:19: error: R12 and W-10 have opposite signs and |R| > |W|)
G00 X60 Z0;
G94 X20 Z-10 F0.1 R12;
