(expect: 2:12: error: malformed number in X20.3.)
(粗车端面) G00 X20.3.;
