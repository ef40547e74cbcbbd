#pragma once
// A word no code of its block used, when the reason is known: another control's word (with the
// flag or setting that reads it), or machinery this lathe lacks (a C or B axis, a second
// spindle). block_executor.cpp says it in place of "not used by any code".

#include <optional>
#include <string>

#include "interp/control/control_parameters.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

std::optional<std::string> missingMachineryOf(const Word& word, const ParsedBlock& block, const ControlParameters& control);

}  // namespace lathesim::interp
