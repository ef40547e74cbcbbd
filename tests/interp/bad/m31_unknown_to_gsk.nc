(expect: 3:12: error: unknown M code M31: expected one of)
(a Haas chip auger code on the GSK980TDi, whose machine M codes it is not)
G00 X40 Z5 M31
