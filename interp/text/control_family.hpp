#pragma once
// Programs written for controls of another family, recognised from their own syntax so that
// they are refused saying what they are, rather than failing on their first unknown word:
//   Okuma OSP           a first line that opens with '$' (`$PART.MIN%`)
//   Philips 432/532     a `%PM` header line
//   LinuxCNC            O-word subroutines and flow (`o100 sub`, `o<name> call`, `o101 if`),
//                       named parameters `#<name>`, G64 with a P tolerance
//   Heidenhain          `BEGIN PGM`
//   Siemens Sinumerik   DIAMON/DIAMOF, CYCLE95 and the like
// Text inside ( ) comments is never evidence.

#include <optional>
#include <string>
#include <string_view>

#include "interp/text/paged_text.hpp"

namespace lathesim::interp {

struct ForeignProgram {
  int line = 0;
  int column = 0;
  std::string family;    // e.g. "Okuma OSP"
  std::string evidence;  // what gave it away, as written
};

std::optional<ForeignProgram> recogniseForeignProgram(PagedText text);

}  // namespace lathesim::interp
