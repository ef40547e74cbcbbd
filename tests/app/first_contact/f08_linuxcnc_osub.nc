G21 G18
o100 sub
G01 X20 F0.2
o100 endsub
o100 call
M2
