// Writing a swept region into the stock's level set, touching as little as possible. The
// region is a shape (below): revolved (a turning cut, the bar itself), helical (a thread
// pass) or a straight slot (a cut with the spindle stopped); the writer asks a shape only how
// a cube of voxels lies to it and what its distance is over a column of voxels, so every
// shape shares the one classification and the one voxel write.
//
// The work that cannot be avoided is proportional to the surface a cut creates or passes,
// so the grid is visited coarse to fine: 128³ blocks the region cannot reach are skipped,
// blocks it covers entirely become one tile, and only the leaves (8³ voxels) near the
// region's boundary are written voxel by voxel. Reading and writing voxels runs in
// parallel; changing the tree's shape (adding leaves and tiles) is serial, as OpenVDB
// requires, but only links nodes that were prepared in parallel.

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <tuple>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "sim/column_write.hpp"
#include "sim/stock_grid.hpp"

namespace lathesim::sim {
namespace {

enum class Reach { None, Partly, Covers };

// How a cube of voxels (centre x, y, z in mm, half-diagonal in mm) lies to a region whose
// distance at the centre is `psi` and changes by at most `slope` per mm: out of the band's
// reach, wholly inside, or partly.
Reach reachOf(double psi, double slope, double halfDiagonal, double band) {
  const double reach = slope * halfDiagonal + band;
  return psi > reach ? Reach::None : psi < -reach ? Reach::Covers : Reach::Partly;
}

// The shapes. Each gives: the bounds of the revolved region that contains it (lowerBound,
// upperBound, maxRadius: which blocks to look at and which ring of columns), a Local (what is
// kept of it near one place, to evaluate there), the whole as a Local, the subset near a point,
// the reach of a cube, and the distance over a column of voxels (x, y, z0 + k·dz).

// A solid of revolution: distances are 2D, of (ρ, z); exact, so slope 1.
struct RevolvedShape {
  const RevolvedRegion& region;
  const RevolvedRegion* changes = nullptr;  // where the write can change anything (cut_history.hpp), or all of it
  using Local = RevolvedRegion;

  const RevolvedRegion* changeExtent() const { return changes; }
  // Whether a voxel within `halfDiagonal` of (x, y, z) can lie within `margin` of the change
  // bound (`band` of it, and a ghost's reach beyond).
  bool mayChange(double x, double y, double z, double halfDiagonal, double margin, double, double h) const {
    const double reach = halfDiagonal + margin;
    return !changes || changes->signedDistance(std::sqrt(x * x + y * y), z, reach + h) <= reach;
  }
  const RevolvedRegion& bounds() const { return region; }
  const Local& whole() const { return region; }
  void nearInto(double x, double y, double z, double radius, Local& out) const {
    region.nearInto(std::sqrt(x * x + y * y), z, radius, out);
  }
  static bool empty(const Local& local) { return local.empty(); }
  static Reach reach(const Local& local, double x, double y, double z, double halfDiagonal, double band, double h) {
    return reachOf(local.signedDistance(std::sqrt(x * x + y * y), z, halfDiagonal + band + h), 1.0, halfDiagonal, band);
  }
  static void column(const Local& local, double x, double y, double z0, double dz, double cap,
                     double (&out)[RevolvedRegion::kColumn]) {
    local.signedDistanceColumn(std::sqrt(x * x + y * y), z0, dz, cap, out);
  }
};

// A region that is not revolved (a thread pass, a cut with the spindle stopped): its revolved
// hull bounds it and decides what is out of reach; its own distance, with its slope, decides
// the rest. Its Local is the whole sweep (a tool outline is small: nothing to subset).
// A cube is taken as covered (filled as one tile, with no voxel's distance taken) only when
// its centre lies deeper inside than the distance can rise over its half-diagonal: so the
// distance must never read deeper than the region is, its ends included (a groove stops in
// the face where the pass ended: helical_sweep.cpp bounds the depth by it). Near the axis the
// helix's slope has no bound and nothing is covered. Only the bar itself is written with Add,
// and it is revolved; these shapes only remove. A thread pass may come with a bound on where it
// can change anything (thread_history.hpp); a slot never does.
template <class Sweep>
struct SweptShape {
  const Sweep& sweep;
  const ThreadChangeBound* changes = nullptr;
  struct Local {
    const Sweep* sweep = nullptr;
  };

  const RevolvedRegion& bounds() const { return sweep.hull(); }
  const RevolvedRegion* changeExtent() const { return changes ? &changes->extent() : nullptr; }
  bool mayChange(double x, double y, double z, double halfDiagonal, double margin, double band, double) const {
    return !changes || changes->mayChange(x, y, z, halfDiagonal + (margin - band), band);
  }
  Local whole() const { return {&sweep}; }
  void nearInto(double, double, double, double, Local& out) const { out.sweep = &sweep; }
  static bool empty(const Local& local) { return local.sweep == nullptr; }
  static Reach reach(const Local& local, double x, double y, double z, double halfDiagonal, double band, double h) {
    const double rho = std::sqrt(x * x + y * y);
    if (reachOf(local.sweep->hull().signedDistance(rho, z, halfDiagonal + band + h), 1.0, halfDiagonal, band) ==
        Reach::None)
      return Reach::None;
    const double slope = slopeOf(*local.sweep, rho - halfDiagonal);
    if (!std::isfinite(slope)) return Reach::Partly;
    return reachOf(local.sweep->signedDistance(x, y, z, slope * halfDiagonal + band + h), slope, halfDiagonal, band);
  }
  static void column(const Local& local, double x, double y, double z0, double dz, double cap,
                     double (&out)[RevolvedRegion::kColumn]) {
    local.sweep->signedDistanceColumn(x, y, z0, dz, cap, out);
  }
  static double slopeOf(const HelicalSweep& helix, double rhoMin) { return helix.lipschitzAt(rhoMin); }
  static double slopeOf(const StraightSlot&, double) { return 1.0; }  // an exact distance
};

enum class Action {
  Update,   // an existing leaf the region's boundary passes through
  Densify,  // a tile the region's boundary passes through: becomes a leaf first
  Fill,     // a leaf or tile the region covers entirely: becomes one tile
  FillSub,  // a 32³ sub-block the region covers entirely: each of its leaves and tiles
            // not yet in the region's state becomes a tile in it
};

struct Task {
  Coord origin;
  int level = 1;  // tree level of a Fill: 1 = one leaf's extent, 2 = a 128³ block
  Action action = Action::Update;
  Leaf* leaf = nullptr;      // Update: the leaf; Densify: the leaf made for the tile
  float tileValue = 0.0f;    // Densify: the value the new leaf starts from
  double insideBefore = 0;   // Fill: material voxels it held before
  std::uint8_t quietQuarters = 0;  // Update, Densify: bit q set where quarter q changes nothing
};

// A leaf with the quarters of it that the write can leave alone (see reachOfQuarters).
struct LeafWrite {
  Leaf* leaf;
  std::uint8_t quietQuarters;
};

template <class Shape>
class RegionWriter {
  using Local = typename Shape::Local;

 public:
  RegionWriter(StockGrid& stock, const Shape& shape, RegionWrite how)
      : stock_(stock), shape_(shape), h_(stock.voxel), bg_(stock.background),
        sign_(how == RegionWrite::Add ? 1.0 : -1.0), removing_(how == RegionWrite::Remove),
        leafReach_(0.5 * std::sqrt(3.0) * (kLeafDim - 1) * h_ + bg_),
        blockReach_(0.5 * std::sqrt(3.0) * (kNode1Dim - 1) * h_ + bg_),
        changeMargin_(bg_ + 2.0 * h_), column_(ColumnWrite::of(sign_, h_, bg_)) {}

  double run() {
    std::vector<Task> tasks = classify();
    std::vector<LeafWrite> writes = restructure(tasks);
    std::vector<double> insideLost = writeVoxels(writes);
    std::vector<Leaf*> leaves(writes.size());
    std::transform(writes.begin(), writes.end(), leaves.begin(), [](const LeafWrite& w) { return w.leaf; });
    // Only a write that changed something can leave a ghost (a grazing rapid cannot).
    const bool changedAny = insideLostTotal_ != 0.0 || std::any_of(insideLost.begin(), insideLost.end(),
                                                                    [](double lost) { return lost != 0.0; });
    if (removing_ && changedAny) clearGhostSheets(leaves, insideLost);
    pruneUniformLeaves(leaves);
    for (double lost : insideLost) insideLostTotal_ += lost;
    return insideLostTotal_ * h_ * h_ * h_;
  }

 private:
  // u = sign·φ, so that both writes read u ← min(u, ψ): "filled" is u = −bg.
  double u(float phi) const { return sign_ * phi; }
  float filledValue() const { return static_cast<float>(-sign_ * bg_); }

  // How the cube of dim³ voxels at `origin` lies to the region (seen through `local`).
  Reach reachOfCube(const Local& local, const Coord& origin, int dim) const {
    const double half = 0.5 * (dim - 1);
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * (dim - 1) * h_;
    return Shape::reach(local, (origin.x() + half) * h_, (origin.y() + half) * h_, (origin.z() + half) * h_,
                        halfDiagonal, bg_, h_);
  }
  Local near(const Coord& origin, int dim, double radius) const {
    const double half = 0.5 * (dim - 1);
    Local local;
    shape_.nearInto((origin.x() + half) * h_, (origin.y() + half) * h_, (origin.z() + half) * h_, radius, local);
    return local;
  }

  // The index box of the revolved `bounds` grown by `marginMm`.
  openvdb::CoordBBox boxAround(const RevolvedRegion& bounds, double marginMm) const {
    const double rMax = bounds.maxRadius() + marginMm;
    return openvdb::CoordBBox(Coord(stock_.toIndexFloor(-rMax), stock_.toIndexFloor(-rMax),
                                    stock_.toIndexFloor(bounds.lowerBound().y() - marginMm)),
                              Coord(stock_.toIndexCeil(rMax), stock_.toIndexCeil(rMax),
                                    stock_.toIndexCeil(bounds.upperBound().y() + marginMm)));
  }

  openvdb::CoordBBox candidateBox() const {
    openvdb::CoordBBox box = boxAround(shape_.bounds(), blockReach_);
    if (removing_) box.intersect(stock_.materialBounds);  // nothing to remove outside it
    if (const RevolvedRegion* extent = shape_.changeExtent()) box.intersect(boxAround(*extent, changeMargin_ + h_));
    return box;
  }

  // Whether the cube of dim³ voxels at `origin` can hold a voxel this write changes, or a
  // ghost beside one (a neighbour within √3 voxels): only within the band of the shape's
  // change bound, spread by the cube's half-diagonal and that neighbour.
  bool mayChange(const Coord& origin, int dim) const {
    const double half = 0.5 * (dim - 1);
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * (dim - 1) * h_;
    return shape_.mayChange((origin.x() + half) * h_, (origin.y() + half) * h_, (origin.z() + half) * h_, halfDiagonal,
                            changeMargin_, bg_, h_);
  }

  double node1InsideVoxels(const Node1* node, float tileValue) const {
    if (!node) return insideFraction(tileValue, h_) * Node1::NUM_VOXELS;
    double sum = 0.0;
    for (auto it = node->cbeginChildOn(); it; ++it) sum += stock_.leafInsideVoxels(*it);
    for (auto it = node->cbeginValueAll(); it; ++it) sum += insideFraction(*it, h_) * Leaf::NUM_VOXELS;
    return sum;
  }

  // 1. Which blocks and leaves the region changes, and how (parallel, read-only).
  std::vector<Task> classify() const {
    const openvdb::CoordBBox box = candidateBox();
    if (box.empty()) return {};
    std::vector<Coord> blocks;
    const auto alignDown = [](int i, int dim) { return i & ~(dim - 1); };
    for (int x = alignDown(box.min().x(), kNode1Dim); x <= box.max().x(); x += kNode1Dim)
      for (int y = alignDown(box.min().y(), kNode1Dim); y <= box.max().y(); y += kNode1Dim)
        for (int z = alignDown(box.min().z(), kNode1Dim); z <= box.max().z(); z += kNode1Dim) blocks.emplace_back(x, y, z);

    tbb::enumerable_thread_specific<std::vector<Task>> found;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1), [&](const auto& range) {
      auto accessor = stock_.grid->getAccessor();
      auto& tasks = found.local();
      for (std::size_t b = range.begin(); b != range.end(); ++b) {
        const Coord& block = blocks[b];
        const Reach reach = reachOfCube(shape_.whole(), block, kNode1Dim);
        if (reach == Reach::None || !mayChange(block, kNode1Dim)) continue;  // out of reach
        const Node1* node = accessor.template probeConstNode<Node1>(block);
        const float tile = accessor.getValue(block);
        if (!node && u(tile) <= -bg_) continue;  // already entirely in the region's state
        if (reach == Reach::Covers) {
          tasks.push_back({block, 2, Action::Fill, nullptr, 0.0f, node1InsideVoxels(node, tile)});
          continue;
        }
        classifyLeaves(block, box, accessor, tasks);
      }
    });
    std::vector<Task> tasks;
    for (auto& list : found) tasks.insert(tasks.end(), list.begin(), list.end());
    // The threads found them in no fixed order, and the volume lost is summed in task order:
    // sorted, the same write gives the same figure to the last bit. By 128³ block first, as
    // restructure() needs a block's tasks together.
    const auto key = [](const Task& t) { return std::make_tuple(t.origin & ~(kNode1Dim - 1), t.origin, t.level, t.action); };
    std::sort(tasks.begin(), tasks.end(), [&](const Task& a, const Task& b) { return key(a) < key(b); });
    return tasks;
  }

  template <typename Accessor>
  void classifyLeaves(const Coord& block, const openvdb::CoordBBox& box, Accessor& accessor, std::vector<Task>& tasks) const {
    // 32³ sub-blocks first: a surface crosses a 128³ block as a sheet, so most of its
    // 4096 leaves lie far from it and are dismissed 64 at a time.
    constexpr int kSub = 4 * kLeafDim;
    const double subReach = 0.5 * std::sqrt(3.0) * (kSub - 1) * h_ + bg_;
    for (int sx = block.x(); sx < block.x() + kNode1Dim; sx += kSub)
      for (int sy = block.y(); sy < block.y() + kNode1Dim; sy += kSub)
        for (int sz = block.z(); sz < block.z() + kNode1Dim; sz += kSub) {
          const Coord sub(sx, sy, sz);
          if (!box.hasOverlap(openvdb::CoordBBox(sub, sub.offsetBy(kSub - 1)))) continue;
          // Wholly outside the region: nothing to do. Wholly inside: one task fills its
          // leaves, with no distance to take.
          const Reach reach = reachOfCube(shape_.whole(), sub, kSub);
          if (reach == Reach::None || !mayChange(sub, kSub)) continue;
          if (reach == Reach::Covers) {  // its 64 leaf slots are filled in restructure()
            tasks.push_back({sub, 1, Action::FillSub, nullptr, 0.0f, 0.0});
            continue;
          }
          // Within the sub-block only the pieces and edges near it matter.
          const Local local = near(sub, kSub, subReach + leafReach_ + h_);
          classifyLeavesOf(local, sub, kSub, box, accessor, tasks);
        }
  }

  template <typename Accessor>
  void classifyLeavesOf(const Local& local, const Coord& block, int dim, const openvdb::CoordBBox& box,
                        Accessor& accessor, std::vector<Task>& tasks) const {
    const RevolvedRegion& bounds = shape_.bounds();
    const double rhoMax = bounds.maxRadius() + leafReach_;
    const double rhoMin = bounds.lowerBound().x() > 0.0 ? bounds.lowerBound().x() - leafReach_ : -1.0;
    for (int x = block.x(); x < block.x() + dim; x += kLeafDim)
      for (int y = block.y(); y < block.y() + dim; y += kLeafDim) {
        // A column of leaves whose footprint lies wholly inside or outside the ring the
        // region sweeps is skipped before any distance is taken.
        const double x0 = x * h_, x1 = (x + kLeafDim - 1) * h_, y0 = y * h_, y1 = (y + kLeafDim - 1) * h_;
        const double nearX = std::clamp(0.0, x0, x1), nearY = std::clamp(0.0, y0, y1);
        const double farX = std::max(std::abs(x0), std::abs(x1)), farY = std::max(std::abs(y0), std::abs(y1));
        if (std::sqrt(nearX * nearX + nearY * nearY) > rhoMax || std::sqrt(farX * farX + farY * farY) < rhoMin) continue;
        for (int z = block.z(); z < block.z() + dim; z += kLeafDim) {
          const Coord origin(x, y, z);
          if (!box.hasOverlap(openvdb::CoordBBox(origin, origin.offsetBy(kLeafDim - 1)))) continue;
          const Reach leafReach = reachOfCube(local, origin, kLeafDim);
          if (leafReach == Reach::None || !mayChange(origin, kLeafDim)) continue;
          Leaf* leaf = accessor.probeLeaf(origin);
          const float tile = leaf ? 0.0f : accessor.getValue(origin);
          if (!leaf && u(tile) <= -bg_) continue;
          std::uint8_t quiet = 0;
          const Reach reach = leafReach == Reach::Partly ? reachOfQuarters(local, origin, quiet) : leafReach;
          if (reach == Reach::None) continue;
          if (reach == Reach::Covers) {
            tasks.push_back({origin, 1, Action::Fill, nullptr, 0.0f,
                             leaf ? stock_.leafInsideVoxels(*leaf) : insideFraction(tile, h_) * Leaf::NUM_VOXELS});
            continue;
          }
          tasks.push_back({origin, 1, leaf ? Action::Update : Action::Densify, leaf, tile, 0.0, quiet});
        }
      }
  }

  // A finer look at a leaf the coarse test could not decide: the distance at the centres of
  // its eight 4³ quarters, each with its own (smaller) reach. Sets in `quiet` the bits of the
  // quarters out of the region's reach, where the write changes nothing: step 3 skips a column
  // whose two quarters are quiet.
  Reach reachOfQuarters(const Local& local, const Coord& origin, std::uint8_t& quiet) const {
    bool allBeyond = true, allCovered = true;
    for (int q = 0; q < 8; ++q) {
      const Coord quarter = origin.offsetBy((q & 1) * 4, ((q >> 1) & 1) * 4, ((q >> 2) & 1) * 4);
      const Reach reach = reachOfCube(local, quarter, 4);
      allBeyond &= reach == Reach::None;
      allCovered &= reach == Reach::Covers;
      if (reach == Reach::None) quiet |= static_cast<std::uint8_t>(1 << q);
    }
    return allBeyond ? Reach::None : allCovered ? Reach::Covers : Reach::Partly;
  }

  // 2. Change the tree's shape. Tasks come grouped by 128³ block (classify() emits a
  //    block's tasks together); each block's node is separate memory, so once the nodes
  //    exist (serial, one per block), blocks are restructured in parallel.
  std::vector<LeafWrite> restructure(std::vector<Task>& tasks) {
    struct BlockTasks {
      std::size_t begin, end;
      Node1* node = nullptr;
    };
    std::vector<BlockTasks> blocks;
    const auto blockOf = [](const Coord& c) { return c & ~(kNode1Dim - 1); };
    for (std::size_t t = 0; t < tasks.size(); ++t)
      if (tasks[t].level == 2) blocks.push_back({t, t + 1});
      else if (blocks.empty() || tasks[blocks.back().begin].level == 2 ||
               blockOf(tasks[blocks.back().begin].origin) != blockOf(tasks[t].origin))
        blocks.push_back({t, t + 1});
      else blocks.back().end = t + 1;

    const openvdb::CoordBBox box = candidateBox();
    auto accessor = stock_.grid->getAccessor();
    const double filledFraction = insideFraction(filledValue(), h_);
    for (BlockTasks& block : blocks) {
      const Task& first = tasks[block.begin];
      if (first.level == 2) {  // a whole block filled: one tile, no node needed
        insideLostTotal_ += first.insideBefore - filledFraction * Node1::NUM_VOXELS;
        accessor.addTile(2, first.origin, filledValue(), false);
        continue;
      }
      block.node = accessor.template probeNode<Node1>(first.origin);
      if (!block.node) {  // the block is a tile: split it into a node holding the tile's value
        // Copies: getValue returns a reference into the parent's table, and addTile puts the new
        // node's pointer there before it reads the value (a heap address's bits as a tile).
        const float tile = accessor.getValue(first.origin);
        const bool active = accessor.isValueOn(first.origin);
        accessor.addTile(1, first.origin, tile, active);
        block.node = accessor.template probeNode<Node1>(first.origin);
      }
    }

    // First the fills and updates, then the new leaves: those a fill took out of the tree
    // are used again for the leaves this write makes, rather than freed and allocated anew.
    std::vector<std::vector<LeafWrite>> leavesOf(blocks.size());
    std::vector<std::vector<Leaf*>> sparesOf(blocks.size());
    std::vector<double> lostOf(blocks.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size()), [&](const auto& range) {
      for (std::size_t b = range.begin(); b != range.end(); ++b) {
        if (!blocks[b].node) continue;
        Node1& node = *blocks[b].node;
        for (std::size_t t = blocks[b].begin; t != blocks[b].end; ++t) {
          Task& task = tasks[t];
          if (task.action == Action::Fill) {
            lostOf[b] += task.insideBefore - filledFraction * Leaf::NUM_VOXELS;
            if (Leaf* old = node.template stealNode<Leaf>(task.origin, filledValue(), false)) sparesOf[b].push_back(old);
            else node.addTile(1, task.origin, filledValue(), false);
          } else if (task.action == Action::FillSub) {
            lostOf[b] += fillSubBlock(node, task.origin, box, sparesOf[b]);
          } else if (task.action == Action::Update) {
            leavesOf[b].push_back({task.leaf, task.quietQuarters});
          }
        }
      }
    });
    std::vector<Leaf*> spares;
    for (const auto& list : sparesOf) spares.insert(spares.end(), list.begin(), list.end());
    for (Task& task : tasks)
      if (task.action == Action::Densify && !spares.empty()) {
        task.leaf = spares.back();
        spares.pop_back();
      }
    for (Leaf* leaf : spares) delete leaf;  // more filled than made: not kept past this write

    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size()), [&](const auto& range) {
      for (std::size_t b = range.begin(); b != range.end(); ++b) {
        if (!blocks[b].node) continue;
        Node1& node = *blocks[b].node;
        for (std::size_t t = blocks[b].begin; t != blocks[b].end; ++t) {
          Task& task = tasks[t];
          if (task.action != Action::Densify) continue;
          if (task.leaf) {  // a filled leaf, made to look new
            task.leaf->setOrigin(task.origin);
            task.leaf->fill(task.tileValue, false);
          } else {
            task.leaf = new Leaf(task.origin, task.tileValue, false);
          }
          node.addLeaf(task.leaf);  // the tree owns it from here
          leavesOf[b].push_back({task.leaf, task.quietQuarters});
        }
      }
    });
    std::vector<LeafWrite> leaves;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      insideLostTotal_ += lostOf[b];
      leaves.insert(leaves.end(), leavesOf[b].begin(), leavesOf[b].end());
    }
    return leaves;
  }

  // The leaves and tiles of a covered 32³ sub-block not yet in the region's state (material
  // when removing, air when adding) become tiles in it (within the candidate box, as
  // classifyLeavesOf would have taken them); the leaves go to `spares`. Returns the
  // material voxels lost.
  double fillSubBlock(Node1& node, const Coord& sub, const openvdb::CoordBBox& box, std::vector<Leaf*>& spares) const {
    constexpr int kSub = 4 * kLeafDim;
    const double filledVoxels = insideFraction(filledValue(), h_) * Leaf::NUM_VOXELS;
    double lost = 0.0;
    for (int x = sub.x(); x < sub.x() + kSub; x += kLeafDim)
      for (int y = sub.y(); y < sub.y() + kSub; y += kLeafDim)
        for (int z = sub.z(); z < sub.z() + kSub; z += kLeafDim) {
          const Coord origin(x, y, z);
          if (!box.hasOverlap(openvdb::CoordBBox(origin, origin.offsetBy(kLeafDim - 1)))) continue;
          if (const Leaf* leaf = node.probeConstLeaf(origin)) {
            lost += stock_.leafInsideVoxels(*leaf) - filledVoxels;
            spares.push_back(node.template stealNode<Leaf>(origin, filledValue(), false));
            continue;
          }
          const float tile = node.getTable()[Node1::coordToOffset(origin)].getValue();  // no leaf here: a tile
          if (u(tile) <= -bg_) continue;  // already in the region's state
          lost += insideFraction(tile, h_) * Leaf::NUM_VOXELS - filledVoxels;
          node.addTile(1, origin, filledValue(), false);
        }
    return lost;
  }

  // 3. u ← min(u, ψ) voxel by voxel (parallel: leaves are independent). Returns, per leaf,
  //    the material voxels lost, summed over the voxels that changed.
  std::vector<double> writeVoxels(const std::vector<LeafWrite>& leaves) {
    ghostCandidates_.assign(leaves.size(), Leaf::NodeMaskType());
    std::vector<double> insideLost(leaves.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
      Local local;  // each leaf's subset, in memory reused from leaf to leaf
      for (std::size_t l = range.begin(); l != range.end(); ++l) {
        Leaf& leaf = *leaves[l].leaf;
        const std::uint8_t quiet = leaves[l].quietQuarters;
        const Coord o = leaf.origin();
        shape_.nearInto((o.x() + 3.5) * h_, (o.y() + 3.5) * h_, (o.z() + 3.5) * h_, leafReach_, local);
        if (Shape::empty(local)) continue;
        float* values = leaf.buffer().data();  // written in place: the loop is the hot path
        auto& activeMask = leaf.getValueMask();
        double lost = 0.0;
        for (int i = 0; i < kLeafDim; ++i) {
          const double x = (o.x() + i) * h_;
          for (int j = 0; j < kLeafDim; ++j) {
            const openvdb::Index column = (i << 6) | (j << 3);  // LeafNode<float, 3>::coordToOffset
            const int lowQuarter = (i >> 2) | ((j >> 2) << 1);  // and lowQuarter | 4 above it in Z
            if ((quiet >> lowQuarter) & (quiet >> (lowQuarter | 4)) & 1) continue;
            if (!column_.anyOpen(values + column)) continue;
            double psi[RevolvedRegion::kColumn];
            Shape::column(local, x, (o.y() + j) * h_, o.z() * h_, h_, bg_, psi);
            // A column's eight voxels are one byte of the leaf's masks (LeafNode<float, 3>).
            lost += writeColumn(column_, values + column, psi, activeMask.template getWord<std::uint8_t>(column >> 3),
                                ghostCandidates_[l].template getWord<std::uint8_t>(column >> 3));
          }
        }
        insideLost[l] = lost;
      }
    });
    return insideLost;
  }

  // 4. Coincident faces of two cuts leave "ghost sheets": voxels at φ ≈ 0⁺ with air on
  //    both sides and no sign change. They would count as partly full voxels (about half
  //    a voxel layer over the face) and, where rounding makes them negative, mesh as
  //    paper-thin walls. A ghost is a voxel that could count (−ε < φ < h/2) while none of
  //    its 26 neighbours is material (φ ≤ −ε): on a real surface one always is, since φ
  //    drops by at least h·(|n_x| + |n_y| + |n_z|) ≥ h from a voxel to its neighbour
  //    towards the material along the normal n. (Asking for a neighbour merely lower
  //    would keep a sheet voxel whose neighbour is a lower ghost — along a bar's rim φ
  //    grows outwards — so it would stay after that neighbour is cleared, counted as
  //    material until some later cut passed.) A ghost lies on the face the cut
  //    shares with an earlier one, so within a voxel of this region's boundary: step 3
  //    marks those voxels as it evaluates them — including a sheet voxel on a face through
  //    voxel centres, which keeps its own value (max(0, 0)) while only its neighbour goes.
  void clearGhostSheets(const std::vector<Leaf*>& leaves, std::vector<double>& insideLost) {
    std::vector<std::vector<openvdb::Index>> ghostsOf(leaves.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
      auto accessor = stock_.grid->getConstAccessor();
      for (std::size_t l = range.begin(); l != range.end(); ++l)
        for (auto it = ghostCandidates_[l].beginOn(); it; ++it)
          if (isGhost(accessor, *leaves[l], it.pos())) ghostsOf[l].push_back(it.pos());
    });
    // Cleared only once all are found: the search reads neighbouring leaves.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
      for (std::size_t l = range.begin(); l != range.end(); ++l)
        for (openvdb::Index n : ghostsOf[l]) {
          insideLost[l] += insideFraction(leaves[l]->getValue(n), h_);
          leaves[l]->setValueOff(n, bg_);
        }
    });
  }

  static constexpr openvdb::Index kStride[3] = {64, 8, 1};  // offset steps along x, y, z in a leaf

  float notMaterial() const { return ColumnWrite::materialCeiling(h_); }

  // Voxel n of a leaf. Usually a face neighbour inside the leaf is material and settles it
  // at once; otherwise all 26 neighbours are asked, since where a surface passes exactly
  // through a voxel centre on an edge (a bar's rim meets grid points at Pythagorean
  // radii) the material lies only diagonally. A sheet has air on both sides, diagonals
  // included.
  template <typename Accessor>
  bool isGhost(Accessor& accessor, const Leaf& leaf, openvdb::Index n) const {
    const float* values = leaf.buffer().data();
    const float material = notMaterial();  // at or below
    const int local[3] = {int(n >> 6), int((n >> 3) & 7), int(n & 7)};
    bool onLeafFace = false;
    for (int axis = 0; axis < 3; ++axis) {
      if (local[axis] > 0 && values[n - kStride[axis]] <= material) return false;
      if (local[axis] < kLeafDim - 1 && values[n + kStride[axis]] <= material) return false;
      onLeafFace |= local[axis] == 0 || local[axis] == kLeafDim - 1;
    }
    if (!onLeafFace) {  // all 26 neighbours lie in this leaf
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz)
            if (values[static_cast<int>(n) + dx * 64 + dy * 8 + dz] <= material) return false;
      return true;
    }
    const Coord p = leaf.offsetToGlobalCoord(n);
    // The face neighbours across the leaf's faces settle most of the rest.
    for (int axis = 0; axis < 3; ++axis)
      for (int step : {-1, 1}) {
        const int moved = local[axis] + step;
        if (moved >= 0 && moved < kLeafDim) continue;
        Coord q = p;
        q[axis] += step;
        if (accessor.getValue(q) <= material) return false;
      }
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          if ((dx || dy || dz) && accessor.getValue(p.offsetBy(dx, dy, dz)) <= material) return false;
    return true;
  }

  // 5. Leaves that ended uniform (all air, or all deep material) become tiles.
  void pruneUniformLeaves(const std::vector<Leaf*>& leaves) {
    std::vector<char> uniform(leaves.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
      for (std::size_t l = range.begin(); l != range.end(); ++l) {
        float first;
        bool active;
        uniform[l] = leaves[l]->isConstant(first, active, 0.0f) && !active && std::abs(first) >= bg_;
      }
    });
    auto accessor = stock_.grid->getAccessor();
    for (std::size_t l = 0; l < leaves.size(); ++l) {
      if (!uniform[l]) continue;
      // Copies: addTile takes references and deletes the leaf they would point into.
      const Coord origin = leaves[l]->origin();
      const float value = leaves[l]->getFirstValue();
      accessor.addTile(1, origin, value, false);
    }
  }

  StockGrid& stock_;
  const Shape& shape_;
  const double h_;
  const float bg_;
  const double sign_;
  const bool removing_;
  const double leafReach_;   // a leaf whose centre is farther than this from the boundary is untouched
  const double blockReach_;  // the same for a 128³ block
  const double changeMargin_;  // a changed voxel lies within the band of the change bound; a new ghost within √3 h of one
  const ColumnWrite column_;
  double insideLostTotal_ = 0.0;
  std::vector<Leaf::NodeMaskType> ghostCandidates_;  // per leaf: voxels within a voxel of the boundary that could count
};

}  // namespace

double writeRegion(StockGrid& stock, const RevolvedRegion& region, RegionWrite how, const RevolvedRegion* changes) {
  if (region.empty() || (changes && changes->empty())) return 0.0;
  const RevolvedShape shape{region, changes};
  return RegionWriter<RevolvedShape>(stock, shape, how).run();
}

double writeRegion(StockGrid& stock, const HelicalSweep& sweep, RegionWrite how, const ThreadChangeBound* changes) {
  const SweptShape<HelicalSweep> shape{sweep, changes};
  return RegionWriter<SweptShape<HelicalSweep>>(stock, shape, how).run();
}

double writeRegion(StockGrid& stock, const StraightSlot& slot, RegionWrite how) {
  const SweptShape<StraightSlot> shape{slot};
  return RegionWriter<SweptShape<StraightSlot>>(stock, shape, how).run();
}

}  // namespace lathesim::sim
