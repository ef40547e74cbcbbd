(expect: 2:5: error: malformed number in X20.3.)
G00 X20.3. Z5;
