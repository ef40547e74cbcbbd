(expect: 3:11: error: C90.: this lathe has no C axis)
G00 X30 Z5
G00 X0 Z2 C90.
M30
