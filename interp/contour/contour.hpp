#pragma once
// The finishing contour of a compound cycle (G70–G73): the moves its ns–nf blocks make when
// run from the cycle's start point, as the control reads them. G71/G72 rough against it,
// G73 repeats it shifted, G70 cuts it. Positions are (radius mm, Z mm).

#include <vector>

#include "geometry/rz.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

struct ContourSegment {
  MoveKind kind = MoveKind::Feed;  // Rapid, Feed, ArcCW or ArcCCW
  RZ from{0, 0};
  RZ to{0, 0};
  RZ center{0, 0};  // arcs only
  int line = 0;     // the contour block that made it, for diagnostics
  int column = 0;
};

/// In order: segments[0].from is the point the ns block starts from (the cycle start A),
/// each segment starts where the previous one ended.
using Contour = std::vector<ContourSegment>;

}  // namespace lathesim::interp
