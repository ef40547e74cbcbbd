(expect: 3:1: error: G81 drills on the spindle's axis, but the tool would stand at X20)
G00 X20 Z5
G81 Z-10 R-3 F0.1
