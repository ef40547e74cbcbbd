(expect: 5:26: error: double edge cutting)
(control: haas; a Haas lathe)
(dialect: haas; its one-block G76)
G00 X22. Z5.
G76 X17. Z-20. K1.5 D0.3 P2 F2.
