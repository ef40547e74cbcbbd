(expect: 3:1: error: LinuxCNC)
G18 G21
o100 sub
G01 X10 F0.1
o100 endsub
M2
