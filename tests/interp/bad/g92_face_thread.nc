(expect: 3:9: error: G92 cannot cut a face thread)
G00 X60 Z2;
G92 X40 W0 F2;
