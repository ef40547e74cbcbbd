#pragma once
// The drawing's sizes checked as an inspector checks them: each diameter measured as a
// diameter, each face's position along Z as a length, against the tolerance the drawing
// states for it (or the general tolerance), with the voxel's uncertainty beside the figure.
//
// A diameter is measured on every grid row of the section along its drawn length, except
// within the allowed corner radius plus two voxels of either end (the corners are the
// profile's business): the part's surface crossing nearest the drawn radius, with the
// material on the drawn side, gives the radius there, exact where φ is linear across the
// voxel. A face is measured the same way along the grid columns across it, on those where
// the part beside it (its neighbouring diameter, taper or arc, as made) leaves the face
// bounded on both sides; where none is left, the face is undecided, never a neighbour's
// figure. The least and the greatest value are compared with the limits.
//

#include <optional>
#include <string>
#include <vector>

#include "geometry/meridian_profile.hpp"
#include "measure/deviation.hpp"
#include "measure/drawing.hpp"
#include "measure/verdict.hpp"

namespace lathesim::measure {

/// The tolerance a line of the drawing takes when it states none: ISO 2768-1 of class
/// `generalClass` for its size (a diameter's diameter, a face's distance from `datumZ`, a
/// taper's or an arc's greatest diameter). Its source says which.
Tolerance generalTolerance(const DrawnLine& line, char generalClass, double datumZ);

/// The datum lengths are measured from: the drawing's front face (its greatest Z).
double datumZOf(const std::vector<DrawnLine>& lines);

/// How far from its ends a diameter or a face is measured: the allowed corner radius and two voxels.
inline double sizeMarginMm(double cornerRadiusMm, double voxelMm) { return cornerRadiusMm + 2 * voxelMm; }

struct SizeCheck {
  DrawnLine drawn;
  std::size_t lineIndex = 0;  // in the lines checked
  bool diameter = true;   // else a face: its Z
  bool bore = false;      // a diameter with the material away from the axis
  double nominalMm = 0;   // the drawn diameter, or the face's Z
  Tolerance tolerance;    // applied
  bool stated = false;    // by the drawing's row; else general
  bool measured = false;  // false: the part has no such surface there
  // A face is probed only on columns where the part beside it does not stand over it (an
  // oversize diameter next to a shoulder would be read for the face). false: none is left;
  // the verdict is undecided and the figures below are the drawn ones, not measured.
  bool probed = true;
  double leastMm = 0, greatestMm = 0;  // the measured diameters (or Z), and where
  RZ leastAt{0, 0}, greatestAt{0, 0};
  double uncertaintyMm = 0;
  double outsideMm = 0;  // how far the worse of least/greatest lies beyond its limit (≤ 0 inside)
  double worstMm = 0;    // that one: the measured figure beyond the limits, or the one nearer them
  RZ worstAt{0, 0};
  Verdict verdict = Verdict::Within;
  std::vector<int> lines;  // the program's lines that made the surface there (see surface_causes.hpp)
  int valueLine = 0;       // the block whose X (a diameter) or Z (a face) put the tool there; 0 unknown
};

/// Checks every diameter and face of `lines` in `section` (voxel = section.stepMm), with
/// `generalClass` for those that state no tolerance and `cornerRadiusMm` kept off their ends.
/// `drawing` tells each line's material side. Lines reaching into `ignored` (a thread's zone,
/// which its callout checks) are left out.
std::vector<SizeCheck> checkSizes(const SampledSection& section, const MeridianProfile& drawing,
                                  const std::vector<DrawnLine>& lines, char generalClass, double cornerRadiusMm,
                                  const std::vector<ZRange>& ignored);

}  // namespace lathesim::measure
