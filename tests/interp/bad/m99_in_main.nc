(expect: 3:1: error: M99 in the main program)
G00 X50 Z2
M99
