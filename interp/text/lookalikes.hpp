#pragma once
// Characters that look like G-code but are not: the en dash a word processor puts for a minus,
// a Cyrillic О typed for O, a full-width digit from an East Asian keyboard, a no-break space.
// A control reads only ASCII and alarms on them; lathesim names the character and what was
// meant, so the user can retype it.

#include <optional>
#include <string>
#include <string_view>

namespace lathesim::interp {

struct LookAlike {
  std::string_view name;  // the Unicode name, e.g. "EN DASH"
  std::string_view meant;  // what it stands for, e.g. "-"
};

/// The look-alike `codePoint` (one UTF-8 code point) is, or nullopt.
std::optional<LookAlike> lookAlikeOf(std::string_view codePoint);

/// "U+2013", for messages.
std::string codePointLabel(std::string_view codePoint);

}  // namespace lathesim::interp
