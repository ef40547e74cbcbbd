(expect: 3:5: error: M98 calls O0020, which is neither in this program nor in a file)
O0010
M98 P20
M30
O0021
M99
