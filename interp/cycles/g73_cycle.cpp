// G73 pattern repeating (lathe-cycles.md §4, GSK980TDi 3.23.3). Pass k = 1 … d follows the
// contour translated by s_k = (Δu/2 + Δi·(d−k)/(d−1), Δw + Δk·(d−k)/(d−1)): pass 1 carries
// the whole relief, pass d only the allowance. With A_k = A + s_k, B_k and C_k the ends of
// the shifted ns block and nf block:
//   step 1  rapid  A → A_1, and C_(k−1) → A_k between passes
//   step 2  A_k → B_k, the ns block's move: rapid if it is G00, feed if G01
//   step 3  feed   B_k → C_k along the rest of the shifted contour (arcs stay arcs)
//   step 4  rapid  C_d → A after the last pass
// d = 1 runs as d = 2 on the GSK; a control that runs it once (control parameter
// g73_single_pass) cuts the one pass at the allowance alone (the last pass's shift). Zero-length
// legs are left out.

#include "interp/cycles/g73_cycle.hpp"

#include <algorithm>

namespace lathesim::interp {

std::optional<std::vector<CycleLeg>> patternRepeatLegs(const RZ& start, const Contour& contour,
                                                       std::size_t firstBlockSegments, bool firstBlockRapid,
                                                       const PatternRepeatParams& params, std::size_t maxLegs) {
  const int passes = params.passes == 1 && params.singlePassRunsTwice ? 2 : std::max(params.passes, 1);
  std::vector<CycleLeg> legs;
  const auto add = [&legs](CycleLeg leg) {
    if (leg.from != leg.to) legs.push_back(leg);
  };
  RZ at = start;
  for (int k = 1; k <= passes; ++k) {
    if (legs.size() > maxLegs) return std::nullopt;
    const double share = passes == 1 ? 0.0 : static_cast<double>(passes - k) / (passes - 1);
    const RZ shift(params.allowanceXMm + params.reliefXMm * share,
                   params.allowanceZMm + params.reliefZMm * share);
    add({MoveKind::Rapid, at, start + shift, 1, RZ(0, 0)});
    for (std::size_t i = 0; i < contour.size(); ++i) {
      const ContourSegment& segment = contour[i];
      const bool nsBlock = i < firstBlockSegments;
      MoveKind kind = segment.kind == MoveKind::Rapid ? MoveKind::Feed : segment.kind;
      if (nsBlock) kind = firstBlockRapid ? MoveKind::Rapid : MoveKind::Feed;
      add({kind, segment.from + shift, segment.to + shift, nsBlock ? 2 : 3, segment.center + shift, {},
           segment.line, segment.column});
    }
    at = (contour.empty() ? start : contour.back().to) + shift;
  }
  add({MoveKind::Rapid, at, start, 4, RZ(0, 0)});
  if (legs.size() > maxLegs) return std::nullopt;
  return legs;
}

}  // namespace lathesim::interp
