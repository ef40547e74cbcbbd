#pragma once
// Text from a program, a setup or a file name, made safe to print on a terminal: a program
// that starts with ESC must not drive the user's terminal when an error quotes it back.

#include <string>
#include <string_view>

namespace lathesim::interp {

/// `text` with every character a terminal would act on written out instead: the C0 control
/// codes but tab and newline (ESC becomes `\x1b`, a CR `\x0d`), DEL (`\x7f`), the C1 controls
/// (U+009B becomes `\u009b`), the bidirectional overrides and isolates (U+202A–U+202E,
/// U+2066–U+2069, which reorder what a line shows), and each byte that is not part of
/// well-formed UTF-8 (`\xff`). Everything else, Chinese comments included, is kept.
std::string printable(std::string_view text);

}  // namespace lathesim::interp
