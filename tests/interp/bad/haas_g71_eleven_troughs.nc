(expect: 29:1: error: G71 contour has 11 troughs)
(control: haas; a Haas lathe)
(dialect: haas; its one-block cycles)
G00 X52. Z2.
G71 P10 Q20 U0.5 D2. F0.25
N10 G00 X20.
G01 Z-5.
X30. Z-8.
X26. Z-10.
X30. Z-12.
X26. Z-14.
X30. Z-16.
X26. Z-18.
X30. Z-20.
X26. Z-22.
X30. Z-24.
X26. Z-26.
X30. Z-28.
X26. Z-30.
X30. Z-32.
X26. Z-34.
X30. Z-36.
X26. Z-38.
X30. Z-40.
X26. Z-42.
X30. Z-44.
X26. Z-46.
X30. Z-48.
X26. Z-50.
X30. Z-52.
N20 X50. Z-54.
