(expect: 2:1: error: OD/ID roughing cycle)
G71 U1 R0.5;
