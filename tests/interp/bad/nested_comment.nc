(expect: 2:28: error: closes no comment: comments do not nest, so the '(' at column 19)
G00 X20 Z2 (rough (OD) pass)
M30
