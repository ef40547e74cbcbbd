(expect: 3:21: error: G02 takes the centre as R or as I/K, not both: R5 and K-5 are both given)
G00 X20 Z0;
G02 X30 Z-5 R5 F0.1 K-5;
