(expect: 3:12: error: closes no comment: a comment opens with '(' on the same line)
G00 X20 Z2
G01 X18 Z0 )F0.1
M30
