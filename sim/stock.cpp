// The only translation unit that instantiates OpenVDB's FloatGrid (see stock.hpp for why).

#include "sim/stock.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace lathesim::sim {
namespace {

using Grid = openvdb::FloatGrid;
using Tree = Grid::TreeType;
using Leaf = Tree::LeafNodeType;
using openvdb::Coord;

constexpr int kLeafDim = static_cast<int>(Leaf::DIM);  // 8
// Measured on this kind of machine: a Φ125×112 bar costs 441 MiB at 0.1 mm and 1.44 GiB
// at 0.05 mm, i.e. 56–67 bytes per voxel of its surface. Cutting adds new surface, so the
// estimate allows for three times the bar's own.
constexpr double kBytesPerSurfaceVoxel = 70.0;
constexpr double kSurfaceGrowthAllowance = 3.0;

void initializeOpenVdbOnce() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

double insideFraction(float value, double voxel) { return std::clamp(0.5 - value / voxel, 0.0, 1.0); }

// What a leaf-sized block of the grid needs when a region is applied.
enum class LeafAction { Update, Densify, Fill };
struct LeafTask {
  Coord origin;
  LeafAction action;
};

}  // namespace

std::uint64_t estimatedStockBytes(const StockSpec& spec, double voxelMm) {
  const double r = spec.diameterMm / 2.0;
  const double surfaceMm2 = 2.0 * M_PI * r * r + 2.0 * M_PI * r * spec.lengthMm;
  return static_cast<std::uint64_t>(surfaceMm2 / (voxelMm * voxelMm) * kBytesPerSurfaceVoxel *
                                    kSurfaceGrowthAllowance);
}

std::optional<std::string> gridProblem(const StockSpec& spec, double voxelMm) {
  if (!(voxelMm > 0.0) || !std::isfinite(voxelMm)) return "the voxel size must be a positive number of mm";
  const double longest = std::max(spec.diameterMm, spec.lengthMm);
  if (longest / voxelMm > 1.0e6) return "the stock would span more than a million voxels; use a larger voxel";
  const double needed = static_cast<double>(estimatedStockBytes(spec, voxelMm));
  const double physical = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  const double allowed = 0.6 * physical;  // the mesh and the outputs need the rest
  if (needed > allowed) {
    constexpr double GiB = 1024.0 * 1024.0 * 1024.0;
    char text[256];
    std::snprintf(text, sizeof text,
                  "a %.3g mm voxel needs about %.1f GiB for this stock's level set, more than the %.1f GiB "
                  "this machine can give it (%.0f GiB of memory); use a voxel of at least %.3g mm",
                  voxelMm, needed / GiB, allowed / GiB, physical / GiB, voxelMm * std::sqrt(needed / allowed) * 1.01);
    return std::string(text);
  }
  return std::nullopt;
}

struct Stock::Impl {
  StockSpec spec;
  double voxel;
  float background;    // narrow-band half-width in mm: |φ| is clamped to it
  Grid::Ptr grid;
  openvdb::CoordBBox materialBounds;  // index box that contains all material, now and later

  Impl(const StockSpec& s, double voxelMm)
      : spec(s), voxel(voxelMm), background(static_cast<float>(kHalfBandVoxels * voxelMm)) {
    initializeOpenVdbOnce();
    grid = Grid::create(background);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName("stock");
    const double r = spec.diameterMm / 2.0;
    const int margin = kHalfBandVoxels + 2;
    materialBounds = openvdb::CoordBBox(
        Coord(toIndexFloor(-r) - margin, toIndexFloor(-r) - margin, toIndexFloor(spec.faceZMm - spec.lengthMm) - margin),
        Coord(toIndexCeil(r) + margin, toIndexCeil(r) + margin, toIndexCeil(spec.faceZMm) + margin));
  }

  int toIndexFloor(double mm) const { return static_cast<int>(std::floor(mm / voxel)); }
  int toIndexCeil(double mm) const { return static_cast<int>(std::ceil(mm / voxel)); }

  // Applies a region to the grid in "u-space", u = sign·φ: u ← min(u, ψ).
  // sign +1 adds material (union with the region), sign −1 removes it (φ ← max(φ, −ψ)).
  // Returns the change of enclosed volume (mm³, positive when material was removed).
  double apply(const RevolvedRegion& region, double sign, bool cleanGhosts);

  double leafInsideVoxels(const Leaf& leaf) const {
    double sum = 0.0;
    for (auto it = leaf.cbeginValueAll(); it; ++it) sum += insideFraction(*it, voxel);
    return sum;
  }
};

double Stock::Impl::apply(const RevolvedRegion& region, double sign, bool cleanGhosts) {
  if (region.empty()) return 0.0;
  Tree& tree = grid->tree();
  const double h = voxel;
  const float bg = background;
  const double halfDiagonal = 0.5 * std::sqrt(3.0) * (kLeafDim - 1) * h;
  const double reach = halfDiagonal + bg;  // a leaf farther than this is untouched

  // Candidate leaves: the region's box, grown by the reach, within the material's box
  // (when removing: outside it there is nothing to remove).
  const double rMax = region.maxRadius() + reach;
  openvdb::CoordBBox box(Coord(toIndexFloor(-rMax), toIndexFloor(-rMax), toIndexFloor(region.lowerBound().y() - reach)),
                         Coord(toIndexCeil(rMax), toIndexCeil(rMax), toIndexCeil(region.upperBound().y() + reach)));
  if (sign < 0) box.intersect(materialBounds);
  if (box.empty()) return 0.0;
  const double rhoMin = region.lowerBound().x() > 0.0 ? region.lowerBound().x() - reach : -1.0;
  const auto alignDown = [](int i) { return i & ~(kLeafDim - 1); };
  std::vector<Coord> columns;  // (x, y) leaf origins whose footprint meets the region's ρ range
  for (int x = alignDown(box.min().x()); x <= box.max().x(); x += kLeafDim)
    for (int y = alignDown(box.min().y()); y <= box.max().y(); y += kLeafDim) {
      const double x0 = x * h, x1 = (x + kLeafDim - 1) * h, y0 = y * h, y1 = (y + kLeafDim - 1) * h;
      const double nearX = std::clamp(0.0, x0, x1), nearY = std::clamp(0.0, y0, y1);
      const double farX = std::max(std::abs(x0), std::abs(x1)), farY = std::max(std::abs(y0), std::abs(y1));
      if (std::hypot(nearX, nearY) > rMax || std::hypot(farX, farY) < rhoMin) continue;
      columns.emplace_back(x, y, 0);
    }

  // 1. Classify leaf-sized blocks (parallel, read-only).
  const float filled = static_cast<float>(-bg * sign);  // φ of a block entirely inside the region
  tbb::enumerable_thread_specific<std::vector<LeafTask>> taskLists;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, columns.size()), [&](const auto& range) {
    auto accessor = grid->getConstAccessor();
    auto& tasks = taskLists.local();
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      const double cx = (columns[c].x() + 3.5) * h, cy = (columns[c].y() + 3.5) * h;
      const double rho = std::hypot(cx, cy);
      for (int z = alignDown(box.min().z()); z <= box.max().z(); z += kLeafDim) {
        const double psi = region.signedDistance(rho, (z + 3.5) * h, reach + h);
        if (psi > halfDiagonal + bg) continue;  // the region does not reach this block
        const Coord origin(columns[c].x(), columns[c].y(), z);
        const bool hasLeaf = accessor.probeConstLeaf(origin) != nullptr;
        const double u = sign * accessor.getValue(origin);
        if (!hasLeaf && u <= -bg) continue;  // a tile already entirely in the region's state
        if (psi < -(halfDiagonal + bg)) tasks.push_back({origin, LeafAction::Fill});
        else tasks.push_back({origin, hasLeaf ? LeafAction::Update : LeafAction::Densify});
      }
    }
  });

  // 2. Change the topology (serial: OpenVDB trees are not safe to restructure concurrently).
  double changedVoxels = 0.0;  // inside-voxel count removed (sign −1) or added (sign +1)
  std::vector<Leaf*> leaves;
  std::vector<double> insideBefore;
  for (auto& tasks : taskLists)
    for (const LeafTask& task : tasks) {
      if (task.action == LeafAction::Fill) {
        const Leaf* leaf = tree.probeConstLeaf(task.origin);
        const double before = leaf ? leafInsideVoxels(*leaf) : insideFraction(tree.getValue(task.origin), h) * Leaf::SIZE;
        const double after = insideFraction(filled, h) * Leaf::SIZE;
        changedVoxels += before - after;
        tree.addTile(1, task.origin, filled, false);
      } else {
        leaves.push_back(tree.touchLeaf(task.origin));
      }
    }
  insideBefore.resize(leaves.size());
  std::vector<Leaf::NodeMaskType> changed(leaves.size());
  // A change smaller than this is rounding between the stock's float values and the
  // region's double distance (a tool running along a face it cut before), not a cut.
  const double noChange = 1e-5 * h;

  // 3. Write the region into the leaves (parallel: leaves are independent).
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
    for (std::size_t l = range.begin(); l != range.end(); ++l) {
      Leaf& leaf = *leaves[l];
      insideBefore[l] = leafInsideVoxels(leaf);
      const Coord o = leaf.origin();
      for (int i = 0; i < kLeafDim; ++i) {
        const double x = (o.x() + i) * h;
        for (int j = 0; j < kLeafDim; ++j) {
          const double rho = std::hypot(x, (o.y() + j) * h);
          for (int k = 0; k < kLeafDim; ++k) {
            const openvdb::Index n = Leaf::coordToOffset(Coord(o.x() + i, o.y() + j, o.z() + k));
            const double u = sign * leaf.getValue(n);
            if (u <= -bg) continue;  // already as deep in the region's state as the band allows
            const double psi = region.signedDistance(rho, (o.z() + k) * h, bg);
            if (psi >= u - noChange) continue;
            const double uNew = std::max(psi, -static_cast<double>(bg));
            leaf.setValueOnly(n, static_cast<float>(sign * uNew));
            leaf.setActiveState(n, std::abs(uNew) < bg);
            changed[l].setOn(n);
          }
        }
      }
    }
  });

  // 4. Coincident faces of two cuts leave "ghost sheets": voxels at φ ≈ 0 (± rounding)
  //    with air on both sides. They would count as half-full voxels and, where rounding
  //    makes them negative, mesh as paper-thin walls. A voxel that is not clearly material
  //    (φ > −ε) and has no 6-neighbour that clearly is becomes plain air. Real surfaces
  //    keep their voxels: a face through voxel centres has material one voxel away.
  //    Only voxels this cut changed are looked at: a ghost is always made by a cut.
  if (cleanGhosts) {
    const float notMaterial = static_cast<float>(-1e-3 * h);
    std::vector<std::vector<openvdb::Index>> ghosts(leaves.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
      auto accessor = grid->getConstAccessor();
      for (std::size_t l = range.begin(); l != range.end(); ++l) {
        for (auto it = changed[l].beginOn(); it; ++it) {
          const openvdb::Index n = it.pos();
          if (leaves[l]->getValue(n) <= notMaterial) continue;
          const Coord p = leaves[l]->offsetToGlobalCoord(n);
          bool touchesMaterial = false;
          for (int axis = 0; axis < 3 && !touchesMaterial; ++axis)
            for (int step : {-1, 1}) {
              Coord q = p;
              q[axis] += step;
              if (accessor.getValue(q) <= notMaterial) touchesMaterial = true;
            }
          if (!touchesMaterial) ghosts[l].push_back(n);
        }
      }
    });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
      for (std::size_t l = range.begin(); l != range.end(); ++l)
        for (openvdb::Index n : ghosts[l]) leaves[l]->setValueOff(n, bg);
    });
  }

  // 5. Measure, and turn leaves that ended uniform into tiles.
  std::vector<char> uniform(leaves.size(), 0);
  const double insideAfterTotal = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, leaves.size()), 0.0,
      [&](const auto& range, double sum) {
        for (std::size_t l = range.begin(); l != range.end(); ++l) {
          sum += leafInsideVoxels(*leaves[l]);
          float first;
          bool state;
          uniform[l] = leaves[l]->isConstant(first, state, 0.0f) && !state && std::abs(first) >= bg;
        }
        return sum;
      },
      std::plus<double>());
  double insideBeforeTotal = 0.0;
  for (double v : insideBefore) insideBeforeTotal += v;
  changedVoxels += insideBeforeTotal - insideAfterTotal;
  for (std::size_t l = 0; l < leaves.size(); ++l)
    if (uniform[l]) {
      const Coord origin = leaves[l]->origin();
      const float value = leaves[l]->getFirstValue();
      tree.addTile(1, origin, value, false);
    }
  return changedVoxels * h * h * h;
}

Stock::Stock(const StockSpec& spec, double voxelMm) : impl_(std::make_unique<Impl>(spec, voxelMm)) {
  const double r = spec.diameterMm / 2.0;
  // The bar's cross-section, mirrored across the axis so that it revolves into a cylinder.
  const std::vector<RZ> rectangle{{-r, spec.faceZMm - spec.lengthMm}, {r, spec.faceZMm - spec.lengthMm},
                                  {r, spec.faceZMm}, {-r, spec.faceZMm}};
  impl_->apply(RevolvedRegion({ConvexPolygon::hullOf(rectangle)}), +1.0, false);
}

Stock::~Stock() = default;

double Stock::voxelMm() const { return impl_->voxel; }

double Stock::remove(const RevolvedRegion& region) { return impl_->apply(region, -1.0, true); }

double Stock::volumeMm3() const {
  const Tree& tree = impl_->grid->tree();
  const double h = impl_->voxel;
  std::vector<const Leaf*> leaves;
  leaves.reserve(tree.leafCount());
  for (auto it = tree.cbeginLeaf(); it; ++it) leaves.push_back(&*it);
  const double leafVoxels = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, leaves.size()), 0.0,
      [&](const auto& range, double sum) {
        for (std::size_t l = range.begin(); l != range.end(); ++l) sum += impl_->leafInsideVoxels(*leaves[l]);
        return sum;
      },
      std::plus<double>());
  double tileVoxels = 0.0;
  for (auto it = tree.cbeginValueOff(); it; ++it)
    if (it.isTileValue() && *it < 0.0f) tileVoxels += static_cast<double>(it.getVoxelCount());
  return (leafVoxels + tileVoxels) * h * h * h;
}

TriangleMesh Stock::mesh(double adaptivity) const {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*impl_->grid, points, triangles, quads, 0.0, adaptivity);
  TriangleMesh mesh;
  mesh.vertices.reserve(points.size());
  for (const auto& p : points) mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  // OpenVDB winds its polygons clockwise seen from outside (from the positive side of a
  // level set); reverse them so that normals point out of the material.
  for (const auto& t : triangles) mesh.triangles.push_back({t[0], t[2], t[1]});
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[2], q[1]});
    mesh.triangles.push_back({q[0], q[3], q[2]});
  }
  return mesh;
}

void Stock::writeVdb(const std::filesystem::path& file) const {
  openvdb::io::File out(file.string());
  out.write({impl_->grid});
  out.close();
}

std::uint64_t Stock::activeVoxelCount() const { return impl_->grid->activeVoxelCount(); }
std::uint64_t Stock::memoryBytes() const { return impl_->grid->memUsage(); }

}  // namespace lathesim::sim
