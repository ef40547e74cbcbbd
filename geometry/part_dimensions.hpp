#pragma once
// The sizes a machinist reads off a drawing of a turned part: its main diameters (the longest
// cylindrical faces, outside and bored) and its lengths (overall, and from the right-hand end
// to each shoulder), measured on the part's section.

#include <vector>

#include "geometry/meridian_profile.hpp"

namespace lathesim {

struct DiameterDimension {
  double diameterMm = 0;
  double zLowMm = 0, zHighMm = 0;  // the cylindrical face's extent along Z
  bool bore = false;               // material outside it (a bore) rather than inside
};

struct LengthDimension {
  double zLowMm = 0, zHighMm = 0;      // the two faces it spans
  double radiusLowMm = 0, radiusHighMm = 0;  // how far out each face reaches (extension lines start there)
};

struct PartDimensions {
  std::vector<DiameterDimension> diameters;  // ordered by Z
  std::vector<LengthDimension> lengths;      // the overall length last, the shortest first
};

struct DimensionRules {
  double flatToleranceMm = 0.01;  // a run of surface points this close to its first point's r (or z) is a face
  double minFaceMm = 1.0;         // faces shorter than this are not dimensioned
  int maxDiameters = 4;
  int maxLengths = 4;             // the overall length included
};

/// The main dimensions of the part whose section `profile` is, read on `polylines` (its
/// surface joined, not thinned: chainSegments; a section's surface points lie on the true
/// surface, so those of a flat face agree to far below a voxel). Diameters: the longest cylindrical faces,
/// one per distinct diameter; lengths: from the right-hand end face to the largest shoulders
/// (faces square to the axis), and the overall length from the leftmost to the rightmost
/// point. Nothing for an empty profile.
PartDimensions mainDimensions(const MeridianProfile& profile, const std::vector<std::vector<RZ>>& polylines,
                              const DimensionRules& rules);

}  // namespace lathesim
