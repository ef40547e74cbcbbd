(expect: 4:5: error: M98 calls O7615, which is neither in this program nor in a file: looked for O7615, O7615.nc, O7615.tap … 7615.txt in)
O1000 (MAIN)
G00 X40 Z2
M98 P17615
M30
