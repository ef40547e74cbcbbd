(expect: 4:9: error: division by zero)
G00 X50 Z2
#1 = 0
#2 = 10 / #1
M30
