(expect: 4:1: error: cannot start in an arc block)
G99 M03 S800
G00 X20 Z5
G42 G02 X30 Z0 R5 F0.1
G40 G00 X40
M30
