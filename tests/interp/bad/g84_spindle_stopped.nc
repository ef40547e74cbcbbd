(expect: 3:1: error: G84 taps with the spindle turning)
G00 X0 Z10
G84 Z-20 R-8 F1.5
