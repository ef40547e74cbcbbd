#pragma once
// The words of M98 (Fanuc 0i / GSK980TDi): `M98 P<program>` runs O<program> once;
// P with more than four digits is the repeat count followed by a four-digit program number
// (M98 P31000 runs O1000 three times); Fanuc also takes the count as L (M98 P1000 L3).

#include "interp/text/block_parser.hpp"
#include "interp/execution/program_flow.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// Takes P (and L) from `block`, which holds `m98`.
Result<SubprogramCall> takeSubprogramCall(ParsedBlock& block, const Code& m98);

}  // namespace lathesim::interp
