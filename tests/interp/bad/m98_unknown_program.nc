(expect: 3:5: error: M98 calls O0020 but the program has no block O20)
O0010
M98 P20
M30
O0021
M99
