(expect: 3:1: error: G76 needs P)
G00 X32 Z5;
G76 X27.546 Z-30 Q400 F2;
