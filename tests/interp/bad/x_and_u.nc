(expect: 3:10: error: X20. and U10. both give the X axis)
(control: fanuc-0i-t; the GSK980TDi takes X and ignores U)
G00 X20. U10.;
