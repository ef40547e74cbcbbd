(expect: 2:1: error: Philips)
%PM
N9001
G00 X50 Z2
M30
