(expect: 2:1: error: is not defined in the setup; defined tools: 1, 2)
T0909;
