(expect: 3:1: error: feed rate F is not set)
G00 X100 Z2;
G01 X20 Z-5;
