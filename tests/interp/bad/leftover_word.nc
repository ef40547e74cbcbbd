(expect: 2:9: error: R5 is not used by any code in this block)
G00 X20 R5;
