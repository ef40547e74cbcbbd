(expect: 2:5: error: X has no number)
G00 X Z5;
