(expect: 8:5: error: the program is still in this loop after 1000000 blocks run again)
G00 X50 Z2
N10 #1 = #1 + 1
M98 P100
M30
O100
#2 = #1
M99 P10
