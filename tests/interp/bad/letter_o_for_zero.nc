(expect: 3:6: error: did you mean the digit 0)
G28 U0 W0
G00 GO X0.
M30
