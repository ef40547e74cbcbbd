#pragma once
// How far a simulated part is from its drawing, everywhere on both surfaces.
//
// The parts are solids of revolution (threads aside), so the deviation at a surface point is
// a question in the meridian half-plane (r, z). Both outlines are MeridianProfiles: the
// part's from its level set sampled in the plane y = 0 (surface = the linear zero crossings
// of φ, joined by marching squares; within a small fraction of a voxel of the true surface
// where φ is a distance), the drawing's from its polygon. Two one-sided measures, both signed
// so that positive is excess (material outside the drawing) and negative is gouge
// (material missing inside it):
//  - at each point p of the part's surface (the polyline's vertices: zero crossings of φ on
//    the grid lines, exact where φ is linear along the line; never the chords between them,
//    which cut sharp corners), the drawing's signed distance d_T(p): p outside
//    the drawing means material reaches d_T(p) beyond it (excess), inside means the part's
//    surface lies |d_T(p)| below the drawn one (gouge). Measured normal to the drawing;
//  - at each point q of the drawing's surface (sampled every half voxel; a drawing that is
//    another program's section at its vertices, as the part), minus the part's
//    signed distance −d_S(q) (φ interpolated where it is inside the band, so a drawn corner
//    that the part has too reads under h/4, not the chord's h/√2): the drawn surface buried
//    |d_S| deep in material (excess) or
//    lying d_S out in the air (gouge). This catches what the first misses, e.g. a thin fin
//    of material over a drawn corner.
// The maxima are the larger of both sides (the two-sided Hausdorff distance, split by sign).
// The volumes are the solids of revolution of (part ∖ drawing) and (drawing ∖ part): per
// sample of the section, both insides as the same one-voxel ramp clamp(½ − d/h, 0, 1) (the
// one Stock::volumeMm3 uses), times 2πr·h², so that coinciding surfaces cancel exactly.
// Samples beyond the tolerance are grouped into regions: samples are joined when the
// midpoints between each and its nearest point on the other surface lie within two voxels.

#include <vector>

#include "geometry/meridian_profile.hpp"

namespace lathesim::measure {

struct DeviationSample {
  RZ at{0, 0};       // on the part's surface or on the drawing's
  RZ nearest{0, 0};  // the nearest point of the other surface
  double mm = 0;     // > 0 excess, < 0 gouge
};

struct DeviationRegion {
  bool gouge = false;
  double maxMm = 0;  // the largest |deviation| in the region
  RZ at{0, 0};       // where it is (on the part's surface or the drawing's)
  RZ lower{0, 0};    // bounds (radius, Z) of the region's samples and their nearest points
  RZ upper{0, 0};
  std::vector<RZ> midpoints;  // between each sample and its nearest point: inside the deviation
  std::vector<int> lines;     // gouge: the lines of the moves that cut it (see gouge_causes.hpp)
};

struct DeviationReport {
  double toleranceMm = 0;
  double maxExcessMm = 0, maxGougeMm = 0;  // ≥ 0; 0 when there is none
  RZ maxExcessAt{0, 0}, maxGougeAt{0, 0};
  double excessVolumeMm3 = 0, gougeVolumeMm3 = 0;
  std::vector<DeviationRegion> regions;  // beyond the tolerance, largest first
  std::vector<DeviationSample> samples;  // every sample, both sides
  bool withinTolerance() const { return maxExcessMm <= toleranceMm && maxGougeMm <= toleranceMm; }
};

/// A stretch of Z left out of the comparison (mm): a thread's zone, checked by its callout.
struct ZRange {
  double lowMm = 0, highMm = 0;
  bool contains(double z) const { return z >= lowMm && z <= highMm; }
};

/// Measures `part` (whose samples are `section`) against `drawing`, except in `ignored`.
DeviationReport measureDeviation(const SampledSection& section, const MeridianProfile& part,
                                 const MeridianProfile& drawing, double toleranceMm,
                                 const std::vector<ZRange>& ignored = {});

}  // namespace lathesim::measure
