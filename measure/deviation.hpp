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
// Samples beyond their band (or within the uncertainty of its edge) are grouped into regions:
// samples are joined when the midpoints between each and its nearest point on the other
// surface lie within two voxels.

#include <algorithm>
#include <functional>
#include <optional>
#include <vector>

#include "geometry/meridian_profile.hpp"
#include "measure/verdict.hpp"

namespace lathesim::measure {

/// The deviations allowed at a sample, in the signed measure below (excess > 0): lower ≤ upper.
struct Band {
  double lowerMm = 0, upperMm = 0;
  /// How far `mm` lies outside the band (≤ 0 inside it).
  double beyond(double mm) const { return std::max(mm - upperMm, lowerMm - mm); }
};

struct DeviationSample {
  RZ at{0, 0};       // on the part's surface or on the drawing's
  RZ nearest{0, 0};  // the nearest point of the other surface
  double mm = 0;     // > 0 excess, < 0 gouge
  bool onPart = true;  // `at` is on the part's surface (else on the drawing's)
};

struct DeviationRegion {
  bool gouge = false;
  double maxMm = 0;  // the largest |deviation| in the region
  double beyondMm = 0;  // how far its worst sample lies outside its band (< 0: undecided, inside)
  RZ worstAt{0, 0};     // that sample (on the part's surface or the drawing's)
  RZ worstOnPart{0, 0};  // where the part's surface is there: the sample, or its nearest point
  Band band;            // that sample's band
  Verdict verdict = Verdict::Out;
  RZ at{0, 0};       // where it is (on the part's surface or the drawing's)
  RZ lower{0, 0};    // bounds (radius, Z) of the region's samples and their nearest points
  RZ upper{0, 0};
  std::vector<RZ> midpoints;  // between each sample and its nearest point: inside the deviation
  std::vector<int> lines;     // gouge: the lines of the moves that cut it (see gouge_causes.hpp)
  std::vector<int> madeBy;    // the lines of the moves that made the surface there (surface_causes.hpp)
};

struct DeviationReport {
  double toleranceMm = 0;  // a band of ±toleranceMm everywhere, when no drawing says otherwise
  double uncertaintyMm = 0;  // of each deviation: the voxel's (verdict.hpp)
  double maxExcessMm = 0, maxGougeMm = 0;  // ≥ 0; 0 when there is none
  RZ maxExcessAt{0, 0}, maxGougeAt{0, 0};
  double excessVolumeMm3 = 0, gougeVolumeMm3 = 0;
  std::vector<DeviationRegion> regions;  // not shown within their bands, furthest beyond first
  std::vector<DeviationSample> samples;  // every sample, both sides
  bool withinTolerance() const { return regions.empty(); }
};

/// A stretch of Z left out of the comparison (mm): a thread's zone, checked by its callout.
struct ZRange {
  double lowMm = 0, highMm = 0;
  bool contains(double z) const { return z >= lowMm && z <= highMm; }
};

/// The band a sample's deviation must lie in, by the point of the drawing it is measured at
/// (its own, or its nearest); nullopt: not judged here (a size check judges it).
using BandAt = std::function<std::optional<Band>(const RZ& onDrawing)>;

/// Measures `part` (whose samples are `section`) against `drawing`, except in `ignored`.
/// Samples are judged against `bandAt`, each known to ±`uncertaintyMm`: the regions hold
/// those beyond their band or within the uncertainty of its edge.
DeviationReport measureDeviation(const SampledSection& section, const MeridianProfile& part,
                                 const MeridianProfile& drawing, const BandAt& bandAt, double uncertaintyMm,
                                 const std::vector<ZRange>& ignored = {});

/// The same with one band, ±toleranceMm, everywhere, decided exactly (no uncertainty).
DeviationReport measureDeviation(const SampledSection& section, const MeridianProfile& part,
                                 const MeridianProfile& drawing, double toleranceMm,
                                 const std::vector<ZRange>& ignored = {});

}  // namespace lathesim::measure
