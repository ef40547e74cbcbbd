(expect: 2:9: error: X20 and U10 both give the X axis)
G00 X20 U10;
