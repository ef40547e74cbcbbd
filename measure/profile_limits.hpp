#pragma once
// Which tolerance holds where on the drawing's outline, as a band of the signed deviation
// (deviation.hpp: > 0 excess, < 0 gouge, measured normal to the surface).
//
// A line's tolerance (drawing.hpp: stated on its row, else ISO 2768-1's general one) becomes
// a band normal to it: a diameter's by half (a diameter is two radii), the sign turned by the
// side the material is on — a shaft 0/−0.021 may lie 0.0105 inside its line and nothing
// outside; a bore's excess is its diameter shrinking. A face's tolerance is on its Z; a
// taper's or an arc's, stated, is normal to it, and general, half its greatest diameter's.
//
// Where a size check measures a diameter or a face (off its ends: size_check.hpp), the
// profile is not judged again. Near a corner between two lines the looser of their bands
// holds, widened by what the line's size check found (the same error is reported once, by the
// size), and a corner the drawing lets be rounded (corner_radius) may be: the fillet of that
// radius tangent to both lines lies R − √(R² − (T − s)²) from a line at s from the corner
// (T = R / tan(φ/2) the tangent length, φ the angle between the lines), so that much excess
// is allowed in a concave corner (a nose radius leaves it) and gouge on a convex one (an
// edge broken).

#include <optional>
#include <vector>

#include "geometry/meridian_profile.hpp"
#include "measure/deviation.hpp"
#include "measure/drawing.hpp"

namespace lathesim::measure {

/// The unit normal of a straight line of the drawing pointing out of the material.
RZ outwardNormal(const MeridianProfile& drawing, const DrawnLine& line);

/// A line's tolerance as a band of the signed deviation normal to it.
Band normalBand(const MeridianProfile& drawing, const DrawnLine& line, const Tolerance& tolerance);

class ProfileLimits {
 public:
  /// `sizeMarginMm`: how far from their ends the size checks measure (size_check.hpp).
  ProfileLimits(const MeridianProfile& drawing, std::vector<RZ> outline, const std::vector<DrawnLine>& lines,
                char generalClass, double cornerRadiusMm, double sizeMarginMm);

  /// The band at `onDrawing`, a point of the outline; nullopt where a size check judges it.
  std::optional<Band> at(const RZ& onDrawing) const;

  /// A size check found line `line` lying [lowMm, highMm] from where it is drawn, normal to
  /// it (excess > 0): near its ends that much is its size's finding, not the profile's too.
  void explainedBySize(std::size_t line, double lowMm, double highMm);

  /// A size check could not measure line `line` (SizeCheck::probed): the profile judges it all.
  void notMeasuredBySize(std::size_t line) { sized_[line] = false; }

 private:
  struct Piece {  // one chord of the outline, with its line's band
    RZ a, b;
    std::size_t line;
  };
  struct Corner {
    RZ at;
    double tangentMm = 0;  // T: how far from the corner a fillet of the allowed radius reaches
    bool concave = false;  // the fillet adds material (excess allowed); else it removes it
  };
  std::vector<Piece> pieces_;
  std::vector<Band> bands_;  // per line
  std::vector<bool> sized_;  // per line: a diameter or a face, judged by a size check off its ends
  std::vector<Band> measured_;  // per line: what its size check found (explainedBySize), else empty
  std::vector<DrawnLine> lines_;
  std::vector<Corner> corners_;
  double cornerRadiusMm_ = 0, sizeMarginMm_ = 0;
};

}  // namespace lathesim::measure
