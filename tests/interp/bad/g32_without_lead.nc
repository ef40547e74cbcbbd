(expect: 3:1: error: the lead is not set: G32 needs F)
G00 X30 Z5;
G32 Z-20;
