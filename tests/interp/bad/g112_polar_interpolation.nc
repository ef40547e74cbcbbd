(expect: 4:13: error: needs a C axis and live tooling)
G99 G00 X40 Z2 M03 S800
G01 Z0 F0.1
G00 X60 Z5; G112
M30
