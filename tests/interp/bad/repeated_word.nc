(expect: 2:9: error: X is given twice in this block)
G00 X20 X30;
