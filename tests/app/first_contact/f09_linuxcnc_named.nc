G21 G18
#<depth> = 1.5
G00 X42 Z2
M2
