(expect: 2:10: error: unknown M code M07)
G00 X100 M07;
