(expect: 3:1: error: unknown G code G05)
G00 X100;
G05 X20;
