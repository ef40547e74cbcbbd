(expect: 6:1: error: X#24 at column 5 was left out: #24 is vacant)
G00 X50 Z2
G65 P9000 Z-20
M30
O9000 (a pass to X#24 Z#26: the call gave no X)
G90 X#24 Z#26 F0.2
M99
