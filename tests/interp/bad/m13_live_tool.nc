(expect: 3:1: error: needs live tooling)
G00 X30 Z5
M13 S2000
M30
