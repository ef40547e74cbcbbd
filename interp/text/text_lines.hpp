#pragma once
// A program's text as the lines a person reads: for the pictures' and the report's listings.

#include <string>
#include <string_view>
#include <vector>

namespace lathesim::interp {

/// The lines of `text`, without their line ends ("\n" or "\r\n"); none after a final "\n".
std::vector<std::string> linesOf(std::string_view text);

}  // namespace lathesim::interp
