(expect: 2:1: error: multiple threading cycle)
G76 P010060 Q100 R0.1;
