#pragma once
// G02/G03, circular interpolation in the ZX plane (G18): where the arc's centre is, from
// the block's R or I/K words, and the checks a control makes on them.
//
//   G02/G03 X(U)_ Z(W)_ R_ F_    R the radius: > 0 for an arc up to 180°, < 0 beyond
//   G02/G03 X(U)_ Z(W)_ I_ K_ F_ I, K the vector from the start point to the centre,
//                                I a radius (not a diameter), always incremental
// G02 turns clockwise and G03 counter-clockwise in the drawing view (Z to the right, X up),
// whichever side of the spindle the turret is on. The block makes one move, an ArcCW or
// ArcCCW with its centre; with I/K and the end point equal to the start it is a full circle.

#include <optional>
#include <string>
#include <string_view>

#include "geometry/rz.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// How far the end point's distance from the centre may differ from the start's. The
/// programmed end is never exactly on the circle (rounded coordinates); Fanuc controls
/// accept a small difference and alarm beyond it (PS0020 "over tolerance of radius",
/// parameter 3410, typically 0.01–0.02 mm). We take 0.01 mm, and the same margin for an R
/// shorter than half the chord (rounding in a programmed semicircle).
inline constexpr double kArcRadiusToleranceMm = 0.01;

/// A length word of an arc block (R, I or K), converted to mm by the caller.
struct ArcWord {
  std::string text;  // as written, e.g. "R-5", for messages
  int column = 0;
  double mm = 0;
};

struct ArcRequest {
  std::string_view code;  // "G02" or "G03", for messages
  bool clockwise = true;  // G02
  RZ start{0, 0};         // (radius mm, Z mm)
  RZ end{0, 0};
  std::optional<ArcWord> r, i, k;
  int line = 0;    // the block's line, and the column to blame when no single word is
  int column = 0;  // at fault (the G code, or the block's start)
};

/// The centre (radius mm, Z mm), or what is wrong: both R and I/K, neither, an R too short
/// for the chord, R with end = start (a full circle needs I/K), I/K on the start point, or an
/// end point off the circle by more than kArcRadiusToleranceMm.
Result<RZ> arcCentre(const ArcRequest& request);

}  // namespace lathesim::interp
