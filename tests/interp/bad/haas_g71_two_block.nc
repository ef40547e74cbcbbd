(expect: 4:1: error: G71 in the Haas form is one block)
(control: haas; a Haas lathe)
(dialect: haas; its one-block cycles)
G71 U2. R1.
G71 P10 Q20 U0.5 W0.1 F0.25
N10 G00 X30.
N20 G01 Z-20.
