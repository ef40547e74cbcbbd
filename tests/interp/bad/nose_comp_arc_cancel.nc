(expect: 5:1: error: cannot be cancelled in an arc block)
G99 M03 S800
G00 X20 Z5
G41 G01 Z0 F0.1
G40 G03 X30 Z-5 R5
M30
