(expect: 4:5: error: M97 calls N300 but this program has no block N300)
(control: haas; a Haas lathe)
(dialect: haas; M97 local subprograms)
M97 P300
M30
N100 G01 W-1. F0.1
M99
