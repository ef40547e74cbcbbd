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
// As the controls read them (GSK980TDi §3.4 notes 2–6, lathe-cycles.md §10):
//   R and I/K both given   R wins, I/K are ignored (warned)
//   R, end = start          a 0° arc: no move (warned; a full circle needs I/K)
//   I/K, end off the circle the centre moves onto the chord's bisector, radius |IK| kept, on
//                           the side of the I/K centre, so the arc joins the programmed ends; on
//                           a control that alarms instead (control parameter arc_end_off_circle)
//                           only within the tolerance (arc_radius_tolerance); beyond it the GSK
//                           warns, and alarms when the chord exceeds 2|IK|

#include <optional>
#include <string>
#include <string_view>

#include <vector>

#include "geometry/rz.hpp"
#include "interp/control/control_parameters.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

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
  // How far an end may lie off the circle (and R fall short of half the chord: rounding in a
  // programmed semicircle), and what the control does beyond that.
  double radiusToleranceMm = 0.01;
  ArcEndOffCircle endOffCircle = ArcEndOffCircle::MoveCentre;
};

struct ArcCentre {
  std::optional<RZ> centre;    // (radius mm, Z mm); none: the block makes no move
  std::vector<Error> warnings;  // what the control ignored or moved
};

/// The centre, or what is wrong: neither R nor I/K, an R too short for the chord, I/K on the
/// start point, an I/K end point the control will not reach (see above).
Result<ArcCentre> arcCentre(const ArcRequest& request);

}  // namespace lathesim::interp
