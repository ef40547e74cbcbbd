(expect: 2:10: error: looks like '-' but is not)
G00 X40 Z–5.
M30
