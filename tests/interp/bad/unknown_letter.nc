(expect: 2:9: error: unknown letter 'V')
G00 X20 V5;
