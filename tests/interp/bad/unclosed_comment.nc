(expect: 3:9: error: comment opened here is not closed)
G00 X100;
G00 X20 (rapid in; Z5
