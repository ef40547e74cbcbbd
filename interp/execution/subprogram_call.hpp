#pragma once
// The words of M98 (Fanuc 0i / GSK980TDi): `M98 P<program>` runs O<program> once;
// P with more than four digits is the repeat count followed by a four-digit program number
// (M98 P31000 runs O1000 three times); Fanuc also takes the count as L (M98 P1000 L3).
// Haas's M97 P<N> [L<count>] runs the blocks from N<N> of the same program to their M99.

#include <optional>

#include "interp/text/block_parser.hpp"
#include "interp/execution/program_flow.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// Takes P (and L) from `block`, which holds `m98`.
Result<SubprogramCall> takeSubprogramCall(ParsedBlock& block, const Code& m98);

/// Haas M97 P<N> [L<repeats>]: runs the blocks from N<N> of the same program to their M99.
Result<SubprogramCall> takeLocalSubprogramCall(ParsedBlock& block, const Code& m97);

}  // namespace lathesim::interp
