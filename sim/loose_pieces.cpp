// Part-off: finding the material that no longer hangs together with the chuck's end, and
// taking it out of the stock.
//
// Every cut that can part a bar is revolved, so the stock is a solid of revolution and its
// pieces are the connected regions of its meridian section (a ring is one piece, since it is
// connected all round). The section is read where it is stored (the plane y = 0, x ≥ 0, a plane
// of voxel centres), its material samples (φ < 0) are joined through their four neighbours,
// and the pieces that do not reach the row of samples nearest the chuck (the lowest Z that
// holds material) have come loose. A tube parts when the cut reaches its bore, a bar when it
// reaches the axis or passes it: either way the section falls in two. A loose piece is a
// crumb a cut left behind, not a part, and stays (the mesh leaves such crumbs out), when no
// sample of it lies more than a quarter of a voxel inside — a wall t thick always has a
// sample (t − h)/2 deep, so every piece thicker than one and a half voxels has one, and
// nothing thinner than half a voxel does — or when it holds less than ten voxels' worth of
// material: the pip a turning tool's flank leaves on the axis of a face cut to X0 stands on
// the face by less than a voxel, and the samples see it loose.
//
// A cut that is no solid of revolution (a straight slot cut with the spindle stopped, a thread's
// helix) breaks that premise: a slot through the plane y = 0 to the axis splits the section
// while the material at every other angle still holds the end together. After such a cut a
// piece the section sees loose is taken out only when the level set's interior is in more than
// one piece in 3D (its connected components, crumbs of under ten voxels aside).
//
// The loose pieces are then moved voxel by voxel into a grid of their own: every voxel,
// band and interior tiles alike, belongs to the piece whose material is nearest in the
// section at its own radius and Z, so both grids keep the level set's values where their
// surfaces are.

#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Prune.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include "sim/stock_grid.hpp"

namespace lathesim::sim {
namespace {

constexpr std::uint8_t kStays = 0;
constexpr std::uint8_t kLoose = 1;
constexpr int kUnreached = -1;

/// φ sampled in the meridian plane over a window of sample indices: i (radius, i·h) from i0,
/// k (Z, k·h) from k0; i fastest.
struct Samples {
  int i0 = 0, k0 = 0, rCount = 0, zCount = 0;
  std::vector<float> phi;
  std::size_t at(int i, int k) const { return static_cast<std::size_t>(k) * rCount + i; }  // window-relative
};

void readSamples(const StockGrid& s, Samples& w) {
  w.phi.resize(static_cast<std::size_t>(w.rCount) * w.zCount);
  if (s.table) {  // the stock is revolved and the table holds it: the plane y = 0 is its own
    for (int i = 0; i < w.rCount; ++i) s.table->columnValues(w.i0 + i, 0, w.k0, w.zCount, &w.phi[w.at(i, 0)], w.rCount);
    return;
  }
  const auto accessor = s.grid->getConstAccessor();
  for (int k = 0; k < w.zCount; ++k)
    for (int i = 0; i < w.rCount; ++i) w.phi[w.at(i, k)] = accessor.getValue(Coord(w.i0 + i, 0, w.k0 + k));
}

/// The whole section's extent, over the bar and a band's width beyond (as meridianSection()),
/// not read yet.
Samples wholeSection(const StockGrid& s) {
  const int margin = kHalfBandVoxels + 2;
  Samples all;
  all.k0 = s.toIndexFloor(s.spec.faceZMm - s.spec.lengthMm) - margin;
  all.rCount = s.toIndexCeil(s.spec.diameterMm / 2.0) + margin + 1;
  all.zCount = s.toIndexCeil(s.spec.faceZMm) + margin - all.k0 + 1;
  return all;
}

/// The material samples (φ < 0) labelled by connected piece (kUnreached for air).
struct Pieces {
  std::vector<int> label;  // per sample, as Samples
  int count = 0;
};

Pieces connectedPieces(const Samples& samples) {
  Pieces pieces;
  const int rCount = samples.rCount, zCount = samples.zCount;
  pieces.label.assign(samples.phi.size(), kUnreached);
  std::vector<std::size_t> queue;
  for (std::size_t seed = 0; seed < samples.phi.size(); ++seed) {
    if (samples.phi[seed] >= 0.0f || pieces.label[seed] != kUnreached) continue;
    const int piece = pieces.count++;
    pieces.label[seed] = piece;
    queue.assign(1, seed);
    while (!queue.empty()) {
      const std::size_t n = queue.back();
      queue.pop_back();
      const int i = static_cast<int>(n % rCount), k = static_cast<int>(n / rCount);
      const auto visit = [&](int ii, int kk) {
        if (ii < 0 || ii >= rCount || kk < 0 || kk >= zCount) return;
        const std::size_t m = samples.at(ii, kk);
        if (samples.phi[m] >= 0.0f || pieces.label[m] != kUnreached) return;
        pieces.label[m] = piece;
        queue.push_back(m);
      };
      visit(i - 1, k);
      visit(i + 1, k);
      visit(i, k - 1);
      visit(i, k + 1);
    }
  }
  return pieces;
}

/// The window of samples around a cut (its area, two samples more each way, within the
/// section's extent `all`, whose samples are not read), read from the grid.
Samples samplesAround(const StockGrid& s, const ChangedArea& cut, const Samples& all) {
  const double h = s.voxel;
  Samples w;
  w.i0 = std::max(0, static_cast<int>(std::floor(cut.rhoMin / h)) - 2);
  const int i1 = std::min(all.rCount - 1, static_cast<int>(std::ceil(cut.rhoMax / h)) + 2);
  w.k0 = std::max(all.k0, static_cast<int>(std::floor(cut.zMin / h)) - 2);
  const int k1 = std::min(all.k0 + all.zCount - 1, static_cast<int>(std::ceil(cut.zMax / h)) + 2);
  w.rCount = std::max(0, i1 - w.i0 + 1);
  w.zCount = std::max(0, k1 - w.k0 + 1);
  readSamples(s, w);
  return w;
}

/// Whether the material still hangs together after a cut, seen in the window around it: every
/// piece of material in the window reaches the window's edge, and all that reaches it is one
/// piece. Material only changes inside the window (the cut, and ghosts within a voxel of it),
/// so any path through the material that entered and left the window before the cut can be
/// rerouted through that one piece: what hung together still does. The window's edges along the
/// axis and along the section's own extent are no edges (nothing passes them).
bool hangsTogetherAround(const Samples& w, const Samples& all) {
  if (w.rCount == 0 || w.zCount == 0) return true;
  const Pieces pieces = connectedPieces(w);
  std::vector<char> reachesEdge(pieces.count, 0);
  int edgePiece = kUnreached;
  const bool openLow = w.i0 > 0, openHigh = w.i0 + w.rCount < all.rCount;
  const bool openBelow = w.k0 > all.k0, openAbove = w.k0 + w.zCount < all.k0 + all.zCount;
  for (int k = 0; k < w.zCount; ++k)
    for (int i = 0; i < w.rCount; ++i) {
      const bool edge = (i == 0 && openLow) || (i == w.rCount - 1 && openHigh) || (k == 0 && openBelow) ||
                        (k == w.zCount - 1 && openAbove);
      const int piece = pieces.label[w.at(i, k)];
      if (!edge || piece == kUnreached) continue;
      if (edgePiece != kUnreached && piece != edgePiece) return false;
      edgePiece = piece;
      reachesEdge[piece] = 1;
    }
  return std::all_of(reachesEdge.begin(), reachesEdge.end(), [](char reaches) { return reaches != 0; });
}

/// A loose piece with less material than this many voxels' worth is a crumb.
constexpr double kMinPieceVoxels = 10.0;

/// Which pieces have come loose: those with no sample in the lowest row holding material, a
/// sample deeper than a quarter of a voxel, and more than kMinPieceVoxels of material (each
/// sample standing for its ring, as Stock::materialInside counts). Empty when none has.
std::vector<bool> loosePieces(const Samples& section, const Pieces& pieces, double voxelMm) {
  const double h = voxelMm;
  std::vector<bool> held(pieces.count, false), deep(pieces.count, false);
  std::vector<double> voxels(pieces.count, 0.0);
  int heldRow = -1;
  for (int k = 0; k < section.zCount && heldRow < 0; ++k)
    for (int i = 0; i < section.rCount; ++i)
      if (const int piece = pieces.label[section.at(i, k)]; piece != kUnreached) {
        held[piece] = true;
        heldRow = k;
      }
  for (int k = 0; k < section.zCount; ++k)
    for (int i = 0; i < section.rCount; ++i) {
      const std::size_t n = section.at(i, k);
      const int piece = pieces.label[n];
      if (piece == kUnreached) continue;
      deep[piece] = deep[piece] || section.phi[n] < -0.25 * h;
      const int rho = section.i0 + i;  // in voxels: a ring of 2πρ·h³, the axis's own disc π h³/4
      voxels[piece] += insideFraction(section.phi[n], h) * (rho == 0 ? M_PI / 4.0 : 2.0 * M_PI * rho);
    }
  std::vector<bool> loose(pieces.count, false);
  bool any = false;
  for (int piece = 0; piece < pieces.count; ++piece)
    any |= loose[piece] = !held[piece] && deep[piece] && voxels[piece] > kMinPieceVoxels;
  if (!any) loose.clear();
  return loose;
}

/// Every sample of the section given to the side (kStays, kLoose) whose material is nearest
/// (in steps between four-neighbours, from all material at once): the border between the
/// two runs down the middle of the gap the cut left.
std::vector<std::uint8_t> territories(const Samples& section, const Pieces& pieces,
                                      const std::vector<bool>& loose) {
  const int rCount = section.rCount, zCount = section.zCount;
  std::vector<std::uint8_t> side(section.phi.size(), kStays);
  std::vector<char> reached(section.phi.size(), 0);
  std::deque<std::size_t> queue;
  for (std::size_t n = 0; n < section.phi.size(); ++n)
    if (pieces.label[n] != kUnreached) {
      side[n] = loose[pieces.label[n]] ? kLoose : kStays;
      reached[n] = 1;
      queue.push_back(n);
    }
  while (!queue.empty()) {
    const std::size_t n = queue.front();
    queue.pop_front();
    const int i = static_cast<int>(n % rCount), k = static_cast<int>(n / rCount);
    const auto visit = [&](int ii, int kk) {
      if (ii < 0 || ii >= rCount || kk < 0 || kk >= zCount) return;
      const std::size_t m = section.at(ii, kk);
      if (reached[m]) return;
      reached[m] = 1;
      side[m] = side[n];
      queue.push_back(m);
    };
    visit(i - 1, k);
    visit(i + 1, k);
    visit(i, k - 1);
    visit(i, k + 1);
  }
  return side;
}

/// The side of the section at grid index (x, y, z): the sample at the voxel's own radius,
/// rounded, and Z. Outside the section (air beyond the bar's extent) it stays.
class SideOf {
 public:
  SideOf(const Samples& section, std::vector<std::uint8_t> side)
      : rCount_(section.rCount), zCount_(section.zCount), zFirst_(section.k0), side_(std::move(side)) {}

  std::uint8_t operator()(const Coord& c) const {
    const int i = static_cast<int>(std::lround(std::sqrt(double(c.x()) * c.x() + double(c.y()) * c.y())));
    const int k = c.z() - zFirst_;
    if (i >= rCount_ || k < 0 || k >= zCount_) return kStays;
    return side_[static_cast<std::size_t>(k) * rCount_ + i];
  }

 private:
  int rCount_, zCount_, zFirst_;
  std::vector<std::uint8_t> side_;
};

/// Turns everything of `grid` on the other side than `keep` into air, then prunes it.
void keepOnly(Grid& grid, const SideOf& sideOf, std::uint8_t keep, float background) {
  Tree& tree = grid.tree();
  std::vector<Leaf*> leaves;
  leaves.reserve(tree.leafCount());
  for (auto it = tree.beginLeaf(); it; ++it) leaves.push_back(&*it);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
    for (std::size_t l = range.begin(); l != range.end(); ++l)
      for (openvdb::Index n = 0; n < Leaf::NUM_VALUES; ++n)
        if (sideOf(leaves[l]->offsetToGlobalCoord(n)) != keep) leaves[l]->setValueOff(n, background);
  });
  // Tiles hold only interior (or air): a tile of material lies wholly inside one piece, so
  // its centre says which.
  auto tile = tree.beginValueAll();
  tile.setMaxDepth(decltype(tile)::LEAF_DEPTH - 1);
  for (; tile; ++tile) {
    if (*tile >= 0.0f) continue;
    if (sideOf(Coord::round(tile.getBoundingBox().getCenter())) == keep) continue;
    tile.setValue(background);
    tile.setValueOff();
  }
  openvdb::tools::pruneLevelSet(tree);
}

/// Whether the material (φ < 0, tiles included) is in more than one 3D piece of ten voxels or
/// more, neighbours joined through their faces.
bool severedIn3D(const StockGrid& s) {
  const auto interior = openvdb::tools::sdfInteriorMask(*s.grid);
  std::vector<openvdb::BoolGrid::Ptr> pieces;
  openvdb::tools::segmentActiveVoxels(*interior, pieces);
  return std::count_if(pieces.begin(), pieces.end(), [](const auto& piece) {
           return static_cast<double>(piece->activeVoxelCount()) >= kMinPieceVoxels;
         }) > 1;
}

}  // namespace

std::unique_ptr<Stock> Stock::takeLoosePieces(const std::optional<ChangedArea>& lastCut, bool notRevolved) {
  Samples section = wholeSection(*impl_);  // its extent; read only when the cut's window cannot tell
  // The table knows which samples of the section turned to air since it was last asked: only
  // there can the material have come apart, so a window around them serves as one around the
  // whole cut (hangsTogetherAround); where none did, the material hangs together still. Around
  // a thin sliver of a cut that window is often too small to see the material on its two sides
  // meet: then the cut's own window is asked, as without the table.
  const MeridianBox flips = impl_->table ? impl_->table->takeMeridianFlips() : MeridianBox{};
  if (lastCut && impl_->table) {
    if (flips.empty()) return nullptr;
    const double h = impl_->voxel;
    const ChangedArea turned{flips.iLow * h, flips.iHigh * h, flips.kLow * h, flips.kHigh * h};
    if (hangsTogetherAround(samplesAround(*impl_, turned, section), section)) return nullptr;
  }
  if (lastCut && hangsTogetherAround(samplesAround(*impl_, *lastCut, section), section)) return nullptr;
  readSamples(*impl_, section);
  const Pieces pieces = connectedPieces(section);
  const std::vector<bool> loose = loosePieces(section, pieces, impl_->voxel);
  if (loose.empty()) return nullptr;
  if (notRevolved && !severedIn3D(*impl_)) return nullptr;
  const SideOf sideOf(section, territories(section, pieces, loose));
  impl_->leaveTable();  // the pieces are split voxel by voxel, in the level set

  auto piece = std::make_unique<StockGrid>(impl_->spec, impl_->voxel);
  piece->grid = impl_->grid->deepCopy();
  piece->materialBounds = impl_->materialBounds;
  keepOnly(*piece->grid, sideOf, kLoose, impl_->background);
  keepOnly(*impl_->grid, sideOf, kStays, impl_->background);
  return std::unique_ptr<Stock>(new Stock(std::move(piece)));
}

}  // namespace lathesim::sim
