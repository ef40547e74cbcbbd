(expect: 3:9: error: B-200.: this lathe has no B axis)
G00 X30 Z5
G00 Z10 B-200.
M30
