#pragma once
// A lathe tool's shape in the (radial, axial) plane, placed so that the PROGRAMMED POINT is
// the origin: the cutter's outline (what is swept and removed), the holder's body (which
// never cuts), the Fanuc imaginary tip number and the nose radius.
//
// Imaginary tip (../shared/spec/lathe-cycles.md §8, iso-tools.md §3): tip number T gives the
// direction s = (sX, sZ) ∈ {−1, 0, 1}² from the nose-radius centre C to the programmed point
// P = C + r·s: 1 (+X,+Z), 2 (+X,−Z), 3 (−X,−Z), 4 (−X,+Z), 5 +Z, 6 +X, 7 −Z, 8 −X, 0 and 9: C
// itself. For tip 3 (an OD turning/facing tool touched off on its low-X and low-Z edges) P is
// the corner (−r, −r) of the nose circle's bounding square: the X and Z touch-off tangents
// cross there. When the nose arc faces both −X and −Z (κr ≥ 90° and κr' ≥ 0, as for L, J,
// G, F styles) the outline's lowest radial point and lowest axial point are the arc's
// tangent points, so after placement the outline's lower bound is exactly (0, 0).

#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/imaginary_tip.hpp"
#include "geometry/iso_holder.hpp"
#include "geometry/iso_insert.hpp"

namespace lathesim {

/// The nose arc is drawn as chords whose sagitta stays below this (mm), so the polygon lies
/// within 0.005 mm inside the true arc; the points where the arc faces ±X and ±Z are always
/// vertices, so touch-off extremes are exact.
inline constexpr double kNoseArcToleranceMm = 0.004;

struct ToolShape {
  ConvexPolygon cutter;                     // [radial, axial] mm from the programmed point
  std::optional<ConvexPolygon> holderBody;  // holder head and shank; never cuts
  int tipNumber = 3;
  double noseRadiusMm = 0.0;
  RZ noseCentre{0, 0};   // from the programmed point
  RZ sharpCorner{0, 0};  // the theoretical sharp corner (turning tools), from the programmed point
};

struct BuiltTool {
  std::optional<ToolShape> tool;
  std::string problem;                // set exactly when tool is not
  std::vector<std::string> warnings;  // e.g. the insert does not match the holder's seat
};

/// The default tip number of a holder: R hand 3, L hand 4 (the same corner mirrored: it cuts
/// toward the tailstock), N hand 8 (touched off on the centre line).
int defaultTipNumber(const IsoHolder& holder);

/// An insert in a holder (§2.11). Refused when the shapes differ; warns when the holder's
/// seat (edge length code, clearance) does not match the insert.
BuiltTool turningTool(const IsoInsert& insert, const IsoHolder& holder, std::optional<int> tipNumber);

/// A grooving or parting blade cutting on its end: width along Z, the end's −Z and +Z corners
/// rounded by leftRadiusMm and rightRadiusMm, usable depth along X. Tips: 3 (the −Z corner,
/// default), 4 (the +Z corner), 8 (the middle of the cutting edge; its nose radius is the
/// smaller corner's). The body is the blade above its depth.
BuiltTool grooveTool(double widthMm, double leftRadiusMm, double rightRadiusMm, double depthMm,
                     std::optional<int> tipNumber);

/// A threading insert: a V of included angle profileDeg symmetric about the radial direction,
/// point toward −X (toward +X for an internal insert), nose radius noseRadiusMm, as tall as the
/// fundamental triangle of the pitch (pitch / (2·tan(angle/2))). Tips: 8 external, 6 internal
/// (the point, default), or 0 (the nose centre).
BuiltTool threadTool(double profileDeg, double pitchMm, double noseRadiusMm, std::optional<int> tipNumber,
                     bool internal = false);

/// A drill on the spindle axis: point angle, diameter, flute length from the point. The
/// programmed point is the drill's point; tip number 0.
BuiltTool drillTool(double diameterMm, double pointAngleDeg, double lengthMm);

}  // namespace lathesim
