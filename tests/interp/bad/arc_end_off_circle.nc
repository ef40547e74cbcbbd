(expect: 5:1: error: the end point X30 Z-5.5 is not on the arc: it is 5.5 mm from the centre X30 Z0, the start point 5 mm; they may differ by at most 0.01 mm)
(control: fanuc-0i-t; the GSK980TDi moves the centre instead)
G99 M03 S800;
G00 X20. Z0.;
G03 X30. Z-5.5 I5. K0. F0.1;
