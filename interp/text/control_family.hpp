#pragma once
// Programs written for controls of another family, recognised from their own syntax so that
// they are refused saying what they are, rather than failing on their first unknown word:
//   Okuma OSP           a first line that opens with '$' (`$PART.MIN%`)
//   Philips 432/532     a `%PM` header line
//   LinuxCNC            O-word subroutines and flow (`o100 sub`, `o<name> call`, `o101 if`),
//                       named parameters `#<name>`, G64 with a P tolerance, G7/G8
//   Heidenhain          `BEGIN PGM`
//   Siemens Sinumerik   DIAMON/DIAMOF, CYCLE95 and the like
//   Fagor 8055/8070     a `%name,MX,` program header; `T1 D1` (tool, then its offset in D,
//                       as Siemens writes it too)
//   Mazak EIA/ISO       G109 (a multi-turret machine's head selection), G53.5/G52.5 (MAZATROL
//                       work coordinates on/off); plain Fanuc-compatible Mazak EIA runs
// Text inside ( ) comments is never evidence.

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "interp/base/paged_text.hpp"

namespace lathesim::interp {

struct ForeignProgram {
  int line = 0;
  int column = 0;
  std::string family;    // e.g. "Okuma OSP"
  std::string evidence;  // what gave it away, as written
};

std::optional<ForeignProgram> recogniseForeignProgram(PagedText text);

/// The program's lines in order, each with its ( ) comments blanked out (columns stay where
/// they were) and cut to kRegexTextChars: the one line walk that the foreign families' signs,
/// the machine's evidence and the stated bar (machine_evidence.hpp) share. `read(lineNumber,
/// line, written)`, `written` the line as written (without its '\n'), returns false to stop.
template <class Read>
void forEachCodeLine(PagedText text, Read&& read);

/// The family `line` (a code line, as forEachCodeLine gives it) shows, or nullopt. `first`:
/// it is the program's first line that is not blank (Okuma's `$` header stands there).
std::optional<ForeignProgram> foreignSignOf(const std::string& line, int lineNumber, bool first);

namespace detail {
/// Line [begin, end) of `text` as a code line, into `line` (whose storage is kept).
void codeLineInto(std::string& line, std::string_view text, std::size_t begin, std::size_t end);
std::string codeLineAt(std::string_view text, std::size_t begin, std::size_t end);
}  // namespace detail

template <class Read>
void forEachCodeLine(PagedText paged, Read&& read) {
  const std::string_view text = paged.view();
  int lineNumber = 0;
  std::size_t begin = 0;
  std::string line;  // one buffer for every line: a long program is read without an allocation a line
  while (begin <= text.size()) {
    paged.readingAt(begin);
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    detail::codeLineInto(line, text, begin, end);
    if (!read(++lineNumber, std::as_const(line), text.substr(begin, end - begin))) return;
    if (end == text.size()) return;
    begin = end + 1;
  }
}

}  // namespace lathesim::interp
