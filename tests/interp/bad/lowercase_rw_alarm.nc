(expect: 4:16: error: R-12 and W10 have opposite signs)
%
g00 x60 z-10;
g94 x20 z0 f.1 r-12;
