(expect: 2:9: error: unknown letter 'B')
G00 X20 B5;
