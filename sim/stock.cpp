// Stock's lifecycle, measurement and output. The cutting itself is in region_writer.cpp.

#include "sim/stock.hpp"

#include <openvdb/tools/Clip.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <numbers>

#include "sim/profile_mesh.hpp"
#include "sim/stock_grid.hpp"

namespace lathesim::sim {
namespace {

// Measured on this kind of machine: a Φ125×112 bar costs 441 MiB at 0.1 mm and 1.44 GiB
// at 0.05 mm, i.e. 56–67 bytes per voxel of its surface. Cutting adds new surface, so the
// estimate allows for three times the bar's own.
constexpr double kBytesPerSurfaceVoxel = 70.0;
constexpr double kSurfaceGrowthAllowance = 3.0;
// Below this many voxels across the bar's smaller dimension, the band (3 voxels each side)
// swallows the part and the figures mean nothing.
constexpr double kMinVoxelsAcrossStock = 20.0;

void initializeOpenVdbOnce() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

}  // namespace

std::uint64_t estimatedBarBytes(const StockSpec& spec, double voxelMm) {
  return static_cast<std::uint64_t>(surfaceAreaMm2(spec) / (voxelMm * voxelMm) * kBytesPerSurfaceVoxel);
}

std::uint64_t estimatedStockBytes(const StockSpec& spec, double voxelMm) {
  return static_cast<std::uint64_t>(static_cast<double>(estimatedBarBytes(spec, voxelMm)) * kSurfaceGrowthAllowance);
}

std::optional<std::string> gridProblem(const StockSpec& spec, double voxelMm) {
  if (!(voxelMm > 0.0) || !std::isfinite(voxelMm)) return "the voxel size must be a positive number of mm";
  const double longest = std::max(spec.diameterMm, spec.lengthMm);
  if (longest / voxelMm > 1.0e6) return "the stock would span more than a million voxels; use a larger voxel";
  const double shortest = std::min(spec.diameterMm, spec.lengthMm);
  if (shortest / voxelMm < kMinVoxelsAcrossStock) {
    char text[160];
    std::snprintf(text, sizeof text, "a %.3g mm voxel is too coarse for a %.3g mm stock; use at most %.3g mm",
                  voxelMm, shortest, shortest / kMinVoxelsAcrossStock);
    return std::string(text);
  }
  // A tube's wall is material from both sides, as a bar's diameter is: it needs as many
  // voxels across as a bar's radius.
  const double wall = (spec.diameterMm - spec.boreMm) / 2.0;
  if (spec.boreMm > 0.0 && wall / voxelMm < kMinVoxelsAcrossStock / 2.0) {
    char text[160];
    std::snprintf(text, sizeof text, "a %.3g mm voxel is too coarse for the tube's %.3g mm wall; use at most %.3g mm",
                  voxelMm, wall, wall / (kMinVoxelsAcrossStock / 2.0));
    return std::string(text);
  }
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

StockGrid::StockGrid(const StockSpec& s, double voxelMm)
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

int StockGrid::toIndexFloor(double mm) const { return static_cast<int>(std::floor(mm / voxel)); }
int StockGrid::toIndexCeil(double mm) const { return static_cast<int>(std::ceil(mm / voxel)); }

namespace {

// Σ clamp(½ − φ/h, 0, 1) over a leaf's 512 values, eight lanes at a time (one AVX2
// register in the AVX2 clone, two SSE2 ones elsewhere).
__attribute__((target_clones("avx2", "default"))) float insideVoxelsOf(const float* values, float inverseVoxel) {
  using Float8 = float __attribute__((vector_size(32)));
  Float8 sum{};  // each lane at most 64: exact enough in float
  for (openvdb::Index n = 0; n < Leaf::NUM_VALUES; n += 8) {
    Float8 v;
    std::memcpy(&v, values + n, sizeof v);
    Float8 fraction = 0.5f - v * inverseVoxel;
    fraction = fraction < 0.0f ? Float8{} : fraction;
    fraction = fraction > 1.0f ? Float8{} + 1.0f : fraction;
    sum += fraction;
  }
  return ((sum[0] + sum[1]) + (sum[2] + sum[3])) + ((sum[4] + sum[5]) + (sum[6] + sum[7]));
}

}  // namespace

double StockGrid::leafInsideVoxels(const Leaf& leaf) const {
  // Straight over the buffer: value iterators cost several times the arithmetic here.
  return insideVoxelsOf(leaf.buffer().data(), static_cast<float>(1.0 / voxel));
}

Stock::Stock(const StockSpec& spec, double voxelMm, RevolvedWrites writes)
    : impl_(std::make_unique<StockGrid>(spec, voxelMm)) {
  const double r = spec.diameterMm / 2.0;
  // The bar's section: a solid bar's mirrored across the axis so that it revolves into a
  // cylinder; a tube's from the bore out, so that it revolves into the tube (the distance in
  // the meridian plane is the tube's own, bore included).
  const double inner = spec.boreMm > 0.0 ? spec.boreMm / 2.0 : -r;
  const std::vector<RZ> rectangle{{inner, spec.faceZMm - spec.lengthMm}, {r, spec.faceZMm - spec.lengthMm},
                                  {r, spec.faceZMm}, {inner, spec.faceZMm}};
  // Every voxel takes its value from the bar's own distance: the band voxel by voxel, the
  // interior as tiles the bar covers entirely. Nothing is left for a flood fill to guess
  // (OpenVDB's signed flood fill reads a 128³ block with no leaves left in it as air).
  const RevolvedRegion bar({ConvexPolygon::hullOf(rectangle)});
  if (writes == RevolvedWrites::Table && impl_->startTable(bar)) return;  // the level set waits until read
  writeRegion(*impl_, bar, RegionWrite::Add);
}

Stock::~Stock() = default;

double Stock::voxelMm() const { return impl_->voxel; }
const StockSpec& Stock::spec() const { return impl_->spec; }

double Stock::remove(const RevolvedRegion& region) {
  if (impl_->table) return impl_->writeThroughTable(region, nullptr);
  return writeRegion(*impl_, region, RegionWrite::Remove);
}
double Stock::remove(const RevolvedRegion& region, const RevolvedRegion& changes) {
  if (impl_->table) return impl_->writeThroughTable(region, &changes);
  return writeRegion(*impl_, region, RegionWrite::Remove, &changes);
}
// What is not revolved ends the table: the level set holds the stock from here on.
double Stock::remove(const HelicalSweep& sweep) {
  impl_->leaveTable();
  return writeRegion(*impl_, sweep, RegionWrite::Remove);
}
double Stock::remove(const StraightSlot& slot) {
  impl_->leaveTable();
  return writeRegion(*impl_, slot, RegionWrite::Remove);
}
double Stock::remove(const HelicalSweep& sweep, const ThreadChangeBound& changes) {
  impl_->leaveTable();
  return writeRegion(*impl_, sweep, RegionWrite::Remove, &changes);
}

double Stock::volumeMm3() const {
  const double h = impl_->voxel;
  if (impl_->table) return impl_->tableInsideVoxels * h * h * h;
  const Tree& tree = impl_->grid->tree();
  std::vector<const Leaf*> leaves;
  leaves.reserve(tree.leafCount());
  for (auto it = tree.cbeginLeaf(); it; ++it) leaves.push_back(&*it);
  // Deterministic: the same split of the leaves, so the same sum to the last bit, every run.
  const double leafVoxels = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, leaves.size(), 256), 0.0,
      [&](const auto& range, double sum) {
        for (std::size_t l = range.begin(); l != range.end(); ++l) sum += impl_->leafInsideVoxels(*leaves[l]);
        return sum;
      },
      std::plus<double>());
  double tileVoxels = 0.0;
  auto it = tree.cbeginValueOff();
  it.setMaxDepth(decltype(it)::LEAF_DEPTH - 1);  // tiles only: the leaves' voxels are summed above
  for (; it; ++it)
    if (*it < 0.0f) tileVoxels += static_cast<double>(it.getVoxelCount());
  return (leafVoxels + tileVoxels) * h * h * h;
}

namespace {

// The table read as a tree by OpenVDB's sampler: the values the grid has once settled.
struct TableValues {
  using ValueType = float;
  const RevolvedTable& table;
  float getValue(const Coord& ijk) const { return table.value(ijk.x(), ijk.y(), ijk.z()); }
};

}  // namespace

double Stock::signedDistanceAt(const RZ& point) const { return signedDistanceAt(point.x(), 0.0, point.y()); }

double Stock::signedDistanceAt(double xMm, double yMm, double zMm) const {
  const openvdb::Vec3d world(xMm, yMm, zMm);
  // One point (a move's start, checked for a warning) need not settle the whole grid.
  if (impl_->table)
    return openvdb::tools::BoxSampler::sample(TableValues{*impl_->table}, impl_->grid->transform().worldToIndex(world));
  const openvdb::tools::GridSampler<Grid, openvdb::tools::BoxSampler> sampler(*impl_->grid);
  return sampler.wsSample(world);
}

void Stock::signedDistancesAt(std::span<const Eigen::Vector3d> points, std::span<double> out) const {
  impl_->settle();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256), [&](const auto& range) {
    const openvdb::tools::GridSampler<Grid, openvdb::tools::BoxSampler> sampler(*impl_->grid);
    for (std::size_t i = range.begin(); i != range.end(); ++i)
      out[i] = sampler.wsSample(openvdb::Vec3d(points[i].x(), points[i].y(), points[i].z()));
  });
}

namespace {

/// `grid`'s surface just inside φ = 0 (see Stock::mesh).
TriangleMesh meshOf(const Grid& grid, double voxelMm, double adaptivity) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  const double isoMm = meshIsoMm(voxelMm);
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, isoMm, adaptivity);
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
  // The mesh as an STL reader will see it; a triangle that then has two corners at one
  // point has no area and goes.
  weldCoincidentVertices(mesh);
  dropCollapsedTriangles(mesh);
  return mesh;
}

}  // namespace

TriangleMesh Stock::mesh(double adaptivity) const {
  // While the table holds the stock, the mesh is its revolved profile (profile_mesh.cpp):
  // already as coarse as its tolerances allow, whatever the adaptivity.
  if (impl_->table)
    if (std::optional<TriangleMesh> revolved = profileMesh(*impl_->table, impl_->voxel, meshIsoMm(impl_->voxel)))
      return std::move(*revolved);
  impl_->settle();
  return meshOf(*impl_->grid, impl_->voxel, adaptivity);
}

TriangleMesh Stock::meshWithVertexEveryVoxel() const {
  if (impl_->table)
    if (std::optional<TriangleMesh> revolved =
            profileMesh(*impl_->table, impl_->voxel, meshIsoMm(impl_->voxel), ProfilePoints::EveryVoxel))
      return std::move(*revolved);
  return mesh(0.0);
}

TriangleMesh Stock::mesh(const Eigen::Vector3d& low, const Eigen::Vector3d& high, int subdivisions) const {
  if (subdivisions < 1) throw std::invalid_argument("Stock::mesh: subdivisions must be at least 1");
  impl_->settle();
  // The grid is clipped a band beyond the box (cheap: what lies in the box), and then
  // intersected with the box as a level set: clip() alone leaves the material open where it
  // cuts it (its interior tiles meet the outside with no band between them to mesh).
  const double h = impl_->voxel;
  const openvdb::Vec3d boxLow(low.x(), low.y(), low.z()), boxHigh(high.x(), high.y(), high.z());
  const double bandMm = (openvdb::LEVEL_SET_HALF_WIDTH + 1) * h;
  const Grid::Ptr inBox =
      openvdb::tools::clip(*impl_->grid, openvdb::BBoxd(boxLow - openvdb::Vec3d(bandMm), boxHigh + openvdb::Vec3d(bandMm)));
  const Grid::Ptr box = openvdb::tools::createLevelSetBox<Grid>(openvdb::BBoxd(boxLow, boxHigh), inBox->transform());
  openvdb::tools::csgIntersection(*inBox, *box);
  if (subdivisions == 1) return meshOf(*inBox, h, 0.0);
  // Finer voxels whose centres split each voxel near the surface (|φ| within 1.5 voxels)
  // k × k × k ways, φ sampled trilinearly there: k − 1 more voxel layers of band each side
  // than the surface needs, and the inside flood-filled from them.
  const int k = subdivisions;
  const Grid::Ptr fine = Grid::create(inBox->background());
  fine->setGridClass(openvdb::GRID_LEVEL_SET);
  fine->setTransform(openvdb::math::Transform::createLinearTransform(h / k));
  Grid::Accessor out = fine->getAccessor();
  const openvdb::tools::GridSampler<Grid, openvdb::tools::BoxSampler> sampler(*inBox);
  const int first = -(k - 1) / 2;  // k odd: centred on the voxel's centre; even: half a fine voxel low
  for (auto v = inBox->cbeginValueOn(); v; ++v) {
    if (!v.isVoxelValue() || std::abs(*v) > 1.5 * h) continue;
    const openvdb::Coord voxel = v.getCoord();
    const openvdb::Coord c(voxel.x() * k + first, voxel.y() * k + first, voxel.z() * k + first);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        for (int l = 0; l < k; ++l) {
          const openvdb::Coord f = c.offsetBy(i, j, l);
          out.setValue(f, static_cast<float>(sampler.wsSample(fine->indexToWorld(f))));
        }
  }
  openvdb::tools::signedFloodFill(fine->tree());
  return meshOf(*fine, h / k, 0.0);
}

namespace {

// io::File::write opens its own stream and never looks at it again, so a full disk would
// leave a truncated .vdb unnoticed. This writes the same archive (seekable, as File writes
// it) into a stream whose state is checked.
class CheckedVdbFile : public openvdb::io::File {
 public:
  using File::File;
  void writeTo(std::ostream& out, const openvdb::GridCPtrVec& grids) const { Archive::write(out, grids, true); }
};

}  // namespace

Stock::Stock(std::unique_ptr<StockGrid> grid) : impl_(std::move(grid)) {}

void Stock::writeVdb(const std::filesystem::path& file, const Stock* part) const {
  // The file's copies share the trees; only their metadata differ. Values are stored as half
  // floats (Blosc-compressed as before): a level set's values lie within the band, ±3 voxels,
  // where a half keeps 11 bits, 1e-4 of a 0.1 mm voxel's band; every OpenVDB reader (Blender,
  // Houdini, ParaView's) reads them back as floats. It halves the file and its writing time.
  const auto fileCopy = [](const StockGrid& grid, const char* name) {
    openvdb::GridBase::Ptr copy = grid.grid->copyGrid();
    copy->setName(name);
    copy->setSaveFloatAsHalf(true);
    return copy;
  };
  impl_->settle();
  if (part) part->impl_->settle();
  openvdb::GridCPtrVec grids{fileCopy(*impl_, "stock")};
  if (part) grids.push_back(fileCopy(*part->impl_, "part"));
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
  CheckedVdbFile(file.string()).writeTo(out, grids);
  out.close();
  if (!out) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
}

bool Stock::isRevolved() const { return impl_->table != nullptr; }

std::uint64_t Stock::activeVoxelCount() const {
  impl_->settle();
  return impl_->grid->activeVoxelCount();
}
std::uint64_t Stock::memoryBytes() const {
  return impl_->grid->memUsage() + (impl_->table ? impl_->table->bytes() : 0);
}

}  // namespace lathesim::sim
