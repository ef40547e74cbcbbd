%
O0400 (NOSE RADIUS COMPENSATION G42: CHAMFER, TAPER AND FILLET WITH A R0.8 TIP 3 TOOL)
N10 G97 S1000 M03 T0101;
N20 G00 X20 Z2;
N30 G99 G42 G01 Z0 F0.1; (start-up: the nose centre ends 0.8 above the face)
N40 X24;
N50 X30 Z-3; (45 degree chamfer)
N60 Z-12;
N70 X36 Z-18; (taper, 3 on the radius over 6)
N80 Z-22;
N90 G02 X40 Z-24 R2; (fillet into the bar's diameter)
N100 G01 X44;
N110 G40 G00 X50; (cancel)
N120 Z2;
N130 X200 Z200 M05;
N140 M30;
%
