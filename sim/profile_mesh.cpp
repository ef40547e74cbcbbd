// The stock's mesh while the revolved table still holds it (revolved_table.hpp).
//
// Why: the level set's mesher (volumeToMesh) makes facets voxel by voxel: millions on a Φ50
// part at 0.1 mm, and nearly all of a run's meshing time (issue 14). While the stock is a solid
// of revolution its whole shape is the table's 2D field φ(ρ, z), one value per radius class
// and Z cell, and the part's profile is where that field crosses the mesh's level. Marching
// squares finds it (linear between neighbouring classes, whose ρ are irregular but
// increasing, and between Z cells); the crossings are joined by the cell edges they lie on
// (exactly, no welding by position); the profile is simplified and revolved about Z
// (geometry/revolved_mesh.hpp). The mesh is closed, a few thousand facets, and has none of
// the voxel mesh's steps.
//
// Tolerances, h the voxel:
// - The level is Stock::mesh's own, a hair inside φ = 0 (meshIsoMm, stock_grid.hpp): a value
//   exactly at the level would put the crossings of two edges on one sample (a segment of no
//   length, and its revolution a sliver), and both meshers then enclose the same volume.
// - The profile is simplified (Douglas–Peucker) to h/100. The values are floats, good to
//   ~1e-7 mm, so a straight cut's crossings lie on a line far closer than that and collapse
//   to its ends; an arc of radius R keeps a chord every √(8·R·h/100) (a fillet R2 at 0.1 mm:
//   every 3.6°). The volume moves by at most h/100 over the curved surface: a fifth of the
//   5 % of a voxel layer measure::checkMesh allows.
// - The angular step is the fewest chords (a multiple of 4, so the mesh reaches ±X and ±Y)
//   for which the circle at the profile's largest radius strays at most h/20 (Φ50 at 0.1 mm:
//   160 steps). A regular n-gon of circumradius r holds sin(2π/n)/(2π/n) of the disc, at every
//   Z alike (a revolved segment's facets are planar trapezoids), so every radius is widened by
//   √((2π/n)/sin(2π/n)): the mesh then encloses the simplified profile's Pappus volume
//   exactly, its vertices lie outside the true circle by ⅔ of the chord's sagitta (≤ h/30)
//   and its chords' middles inside by ⅓ (≤ h/60).

#include "sim/profile_mesh.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "geometry/profile_polylines.hpp"
#include "geometry/revolved_mesh.hpp"

namespace lathesim::sim {
namespace {

// A crossing is named by the cell edge it lies on: between classes c and c + 1 at Z cell k
// (radial), or between Z cells k and k + 1 of class c (axial).
enum class EdgeAxis : std::uint64_t { Radial = 0, Axial = 1 };

struct EdgeCrossing {
  std::uint64_t key;
  RZ point;
};
// The profile within one cell, from crossing to crossing, the material on its right (ρ across,
// z up), as revolvedMesh wants it.
struct ProfileSegment {
  EdgeCrossing from, to;
};

class ProfileScan {
 public:
  ProfileScan(const RevolvedTable& table, double voxelMm, double isoMm)
      : table_(table), h_(voxelMm), iso_(isoMm), cells_(table.chunkCount() * kChunk), kBase_(table.firstCellK()) {}

  /// The crossings of classes c and c + 1 within the chunks `chunks` (ascending).
  void scanPair(int c, const std::vector<int>& chunks, std::vector<ProfileSegment>& out) const {
    const int chunkCount = table_.chunkCount();
    for (const int chunk : chunks) {
      const float* inner = table_.chunkCells(c, chunk);
      const float* outer = table_.chunkCells(c + 1, chunk);
      const bool last = chunk + 1 == chunkCount;  // its last cell has no cell above it
      const float* innerAbove = last ? nullptr : table_.chunkCells(c, chunk + 1);
      const float* outerAbove = last ? nullptr : table_.chunkCells(c + 1, chunk + 1);
      for (int n = 0; n < (last ? kChunk - 1 : kChunk); ++n) {
        // Corners counter-clockwise from (c, k): (c + 1, k), (c + 1, k + 1), (c, k + 1).
        const float v[4] = {inner[n], outer[n], n + 1 < kChunk ? outer[n + 1] : outerAbove[0],
                            n + 1 < kChunk ? inner[n + 1] : innerAbove[0]};
        scanCell(c, kBase_ + chunk * kChunk + n, v, out);
      }
    }
  }

  bool onAxis(std::uint64_t key) const {
    return (key & 1) == static_cast<std::uint64_t>(EdgeAxis::Axial) && (key >> 1) / cells_ == 0;
  }

 private:
  std::uint64_t key(EdgeAxis axis, int c, int k) const {
    return ((static_cast<std::uint64_t>(c) * cells_ + (k - kBase_)) << 1) | static_cast<std::uint64_t>(axis);
  }
  // Where the level lies between a (at the edge's lower class or cell) and b, as a share.
  double share(float a, float b) const { return (iso_ - a) / (static_cast<double>(b) - a); }

  void scanCell(int c, int k, const float (&v)[4], std::vector<ProfileSegment>& out) const {
    bool inside[4];
    int count = 0;
    for (int i = 0; i < 4; ++i) {
      inside[i] = v[i] < iso_;
      count += inside[i] ? 1 : 0;
    }
    if (count == 0 || count == 4) return;
    const double rho0 = table_.classRadiusMm(c), rho1 = table_.classRadiusMm(c + 1);
    // Edge e runs from corner e to corner e + 1: bottom, right, top, left. A crossing shared
    // by two cells is computed from the same values in the same order in both.
    const auto crossing = [&](int e) -> EdgeCrossing {
      switch (e) {
        case 0: return {key(EdgeAxis::Radial, c, k), RZ(rho0 + share(v[0], v[1]) * (rho1 - rho0), k * h_)};
        case 1: return {key(EdgeAxis::Axial, c + 1, k), RZ(rho1, k * h_ + share(v[1], v[2]) * h_)};
        case 2: return {key(EdgeAxis::Radial, c, k + 1), RZ(rho0 + share(v[3], v[2]) * (rho1 - rho0), (k + 1) * h_)};
        default: return {key(EdgeAxis::Axial, c, k), RZ(rho0, k * h_ + share(v[0], v[3]) * h_)};
      }
    };
    // Walking round the cell counter-clockwise, the material is entered across one edge and
    // left across another; the profile runs from the entry to the exit (material on its
    // right). Two exits (opposite corners inside): the material joins through the cell's
    // middle when its mean value is inside, and each exit's entry is then the edge after it;
    // otherwise the corners are apart and each exit's entry is the edge before it.
    int exits[2], exitCount = 0, entry = 0;
    for (int e = 0; e < 4; ++e) {
      if (inside[e] && !inside[(e + 1) % 4]) exits[exitCount++] = e;
      if (!inside[e] && inside[(e + 1) % 4]) entry = e;
    }
    const bool joined = (static_cast<double>(v[0]) + v[1] + v[2] + v[3]) / 4.0 < iso_;
    for (int n = 0; n < exitCount; ++n) {
      const int from = exitCount == 1 ? entry : joined ? (exits[n] + 1) % 4 : (exits[n] + 3) % 4;
      out.push_back({crossing(from), crossing(exits[n])});
    }
  }

  const RevolvedTable& table_;
  double h_, iso_;
  int cells_, kBase_;
};

// The chunks of class c that may hold a crossing with a neighbouring class or cell.
std::vector<int> mixedChunksOf(const RevolvedTable& table, int c) {
  std::vector<int> chunks;
  table.forEachMixedChunk(c, [&](int k0, const float*, std::uint8_t) { chunks.push_back((k0 - table.firstCellK()) / kChunk); });
  return chunks;
}

// The profile's pieces, cell by cell. A cell whose corners all lie in chunks of one value at
// ±band holds no crossing unless two of them are air and solid (+band, −band) side by side:
// values a voxel apart that differ by six voxels, which no level set has; were it so, the
// profile would not close and the caller meshes the level set.
std::vector<ProfileSegment> profileSegments(const RevolvedTable& table, const ProfileScan& scan) {
  const int pairs = table.classCount() - 1;
  constexpr int kPairsPerTask = 256;
  const int tasks = std::max(0, (pairs + kPairsPerTask - 1) / kPairsPerTask);
  std::vector<std::vector<ProfileSegment>> found(tasks);
  tbb::parallel_for(0, tasks, [&](int task) {
    const int first = task * kPairsPerTask, end = std::min(pairs, first + kPairsPerTask);
    std::vector<int> inner = mixedChunksOf(table, first), outer, chunks;
    for (int c = first; c < end; ++c) {
      outer = mixedChunksOf(table, c + 1);
      // Cell (c, k) spans Z cells k and k + 1: the chunk of a mixed corner, or the one below.
      chunks.clear();
      for (const std::vector<int>* list : {&inner, &outer})
        for (const int chunk : *list) {
          chunks.push_back(chunk);
          if (chunk > 0) chunks.push_back(chunk - 1);
        }
      std::sort(chunks.begin(), chunks.end());
      chunks.erase(std::unique(chunks.begin(), chunks.end()), chunks.end());
      scan.scanPair(c, chunks, found[task]);
      inner.swap(outer);
    }
  });
  std::vector<ProfileSegment> segments;
  for (auto& part : found) segments.insert(segments.end(), part.begin(), part.end());
  return segments;
}

// The segments joined crossing to crossing into polylines: open ones from the axis to the
// axis, loops with their first point repeated last (as profile_polylines.hpp has them).
// nullopt when they do not join so (a crossing at the table's edge).
std::optional<std::vector<std::vector<RZ>>> joinSegments(std::vector<ProfileSegment>& segments, const ProfileScan& scan) {
  std::sort(segments.begin(), segments.end(), [](const auto& a, const auto& b) { return a.from.key < b.from.key; });
  for (std::size_t s = 1; s < segments.size(); ++s)
    if (segments[s].from.key == segments[s - 1].from.key) return std::nullopt;
  std::vector<std::uint64_t> ends(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) ends[s] = segments[s].to.key;
  std::sort(ends.begin(), ends.end());
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  const auto startingAt = [&](std::uint64_t key) {
    const auto it = std::lower_bound(segments.begin(), segments.end(), key,
                                     [](const ProfileSegment& s, std::uint64_t k) { return s.from.key < k; });
    return it != segments.end() && it->from.key == key ? static_cast<std::size_t>(it - segments.begin()) : kNone;
  };
  std::vector<bool> used(segments.size(), false);
  std::vector<std::vector<RZ>> lines;
  // Follows the segments from `s` until a crossing no segment starts at (the axis) or `s` again.
  const auto follow = [&](std::size_t s) -> bool {
    std::vector<RZ> line{segments[s].from.point};
    for (std::size_t at = s;;) {
      used[at] = true;
      line.push_back(segments[at].to.point);
      const std::size_t next = startingAt(segments[at].to.key);
      if (next == kNone) {
        if (!scan.onAxis(segments[at].to.key)) return false;
        break;
      }
      if (next == s) {
        line.back() = line.front();
        break;
      }
      if (used[next]) return false;
      at = next;
    }
    lines.push_back(std::move(line));
    return true;
  };
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!std::binary_search(ends.begin(), ends.end(), segments[s].from.key))
      if (!scan.onAxis(segments[s].from.key) || !follow(s)) return std::nullopt;
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!used[s] && !follow(s)) return std::nullopt;
  return lines;
}

// `line` with each segment longer than `lengthMm` split into equal pieces no longer than it.
// (Not the crossings themselves: on a face across the axis there is one at every radius class,
// 4,000 of them over 25 mm at 0.2 mm voxels.)
std::vector<RZ> splitLongerThan(const std::vector<RZ>& line, double lengthMm) {
  std::vector<RZ> split{line.front()};
  for (std::size_t i = 1; i < line.size(); ++i) {
    const RZ from = line[i - 1], to = line[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil((to - from).norm() / lengthMm)));
    for (int n = 1; n < pieces; ++n) split.push_back(from + (to - from) * (static_cast<double>(n) / pieces));
    split.push_back(to);
  }
  return split;
}

}  // namespace

std::optional<TriangleMesh> profileMesh(const RevolvedTable& table, double voxelMm, double isoMm, ProfilePoints points) {
  if (table.classCount() < 2) return std::nullopt;
  const ProfileScan scan(table, voxelMm, isoMm);
  std::vector<ProfileSegment> segments = profileSegments(table, scan);
  std::optional<std::vector<std::vector<RZ>>> joined = joinSegments(segments, scan);
  if (!joined) return std::nullopt;
  std::vector<std::vector<RZ>> profile;
  double largestRadiusMm = 0.0;
  for (const std::vector<RZ>& line : *joined) {
    std::vector<RZ> simplified = simplifyPolyline(line, kProfileToleranceVoxels * voxelMm);
    // A loop thinner than twice the tolerance simplifies to a line there and back: no volume.
    if (simplified.front() == simplified.back() && simplified.size() < 4) continue;
    if (points == ProfilePoints::EveryVoxel) simplified = splitLongerThan(simplified, voxelMm);
    for (const RZ& p : simplified) largestRadiusMm = std::max(largestRadiusMm, p.x());
    profile.push_back(std::move(simplified));
  }
  if (profile.empty()) return TriangleMesh{};
  const double chordToleranceVoxels =
      points == ProfilePoints::Simplified ? kChordToleranceVoxels : kEveryVoxelChordToleranceVoxels;
  const int steps = (angularStepsFor(largestRadiusMm, chordToleranceVoxels * voxelMm) + 3) / 4 * 4;
  const double step = 2.0 * std::numbers::pi / steps;
  const double widening = std::sqrt(step / std::sin(step));
  for (std::vector<RZ>& line : profile)
    for (RZ& p : line) p.x() *= widening;
  return revolvedMesh(profile, steps);
}

}  // namespace lathesim::sim
