(expect: 4:12: error: G03 with R8 cannot cut a full circle)
(a full circle needs I/K: G03 K-8)
G00 X40 Z0;
g03 x40 z0 r8 f0.1;
