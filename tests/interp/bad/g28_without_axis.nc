(expect: 3:1: error: G28 needs X)
G00 X40 Z10
G28 F0.2
