(expect: 4:1: error: the end point X30 Z-5.5 is not on the arc: it is 5.5 mm from the centre X30 Z0, the start point 5 mm)
G99 M03 S800;
G00 X20 Z0;
G03 X30 Z-5.5 I5 K0 F0.1;
