(expect: 2:1: error: this is a program for Okuma OSP)
$PART1.MIN%
G00 X50 Z2
M02
