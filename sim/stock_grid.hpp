#pragma once
// Inside sim only: the OpenVDB grid behind Stock, shared by the files that work on it.
// Including this header costs OpenVDB's compile time; keep it out of public headers.

#include <openvdb/openvdb.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <numbers>

#include "geometry/helical_sweep.hpp"
#include "geometry/revolved_region.hpp"
#include "geometry/straight_slot.hpp"
#include "sim/revolved_table.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {

using Grid = openvdb::FloatGrid;
using Tree = Grid::TreeType;
using Leaf = Tree::LeafNodeType;                 // 8³ voxels
using Node1 = Tree::RootNodeType::ChildNodeType::ChildNodeType;  // 128³ voxels, 16³ leaves
using openvdb::Coord;

inline constexpr int kLeafDim = static_cast<int>(Leaf::DIM);    // 8
inline constexpr int kNode1Dim = static_cast<int>(Node1::DIM);  // 128

/// The share of a voxel inside the material: a ramp one voxel wide across φ = 0, exact
/// for a plane and unbiased on average for any smooth surface.
inline double insideFraction(float value, double voxel) { return std::clamp(0.5 - value / voxel, 0.0, 1.0); }

/// The level the stock's surface is meshed at (mm): a small irrational fraction of a voxel
/// inside φ = 0. Where the surface passes exactly through voxel centres (round dimensions on
/// round voxels: a Φ10 drill at 0.2 mm, a cone's tip on the axis), φ is exactly 0 there, and a
/// mesher puts the vertices of several cells around such a voxel on its centre: one point,
/// many vertices. An STL stores positions, so a reader glues them into one, and edges come out
/// shared by 4–10 triangles. No round dimension lands on this level; it moves those vertices
/// apart by several float steps of a coordinate (0.16 % of a voxel: 8e-5 mm at 0.05 mm voxels)
/// while the volume moves by 0.16 % of a voxel layer.
inline double meshIsoMm(double voxelMm) { return -voxelMm * (std::numbers::sqrt2 - 1.0) / 256.0; }

struct StockGrid {
  StockSpec spec;
  double voxel;
  float background;  // narrow-band half-width in mm: |φ| is clamped to it
  Grid::Ptr grid;
  openvdb::CoordBBox materialBounds;  // index box that contains all material, now and later
  /// While the stock is a solid of revolution, the table holds it (revolved_table.hpp) and
  /// `grid` lags behind until settle(): it is not even built until something reads it. Null
  /// once something not revolved was written.
  std::unique_ptr<RevolvedTable> table;
  /// While the table holds the stock: its material voxels, Σ clamp(½ − φ/h, 0, 1) over every
  /// voxel, kept as the writes report what they lose (the volume needs no pass over anything).
  double tableInsideVoxels = 0.0;

  StockGrid(const StockSpec& s, double voxelMm);

  /// Gives a stock not built yet the bar as a table (revolved_table.hpp), when the table's
  /// memory is small beside what the level set's would be; the level set is then built at the
  /// first settle. Returns false, leaving the stock as it was, when the table is not kept.
  bool startTable(const RevolvedRegion& bar);
  /// Writes into `grid` what the table changed since the last settle, building the level set
  /// first if it was never built (thread-safe: readers that share a const stock may each call
  /// it). Nothing to do without a table.
  void settle() const;
  /// Settles and drops the table: before a write or an edit the table cannot hold.
  void leaveTable();
  /// Writes a revolved region through the table (see writeRegion); the table is left when
  /// the write makes the stock stop being revolved.
  double writeThroughTable(const RevolvedRegion& region, const RevolvedRegion* changes);

  int toIndexFloor(double mm) const;
  int toIndexCeil(double mm) const;
  double leafInsideVoxels(const Leaf& leaf) const;

 private:
  mutable std::mutex settling_;
  /// False while the level set is not built yet (the table holds the stock).
  mutable bool gridBuilt_ = true;
};

/// How a region is written into the level set.
enum class RegionWrite {
  Add,     // φ ← min(φ, ψ): the region becomes material (builds the bar)
  Remove,  // φ ← max(φ, −ψ): the region becomes air (cuts)
};

/// Writes `region` into the stock's grid; returns the volume that stopped being material
/// (mm³; negative when material was added). See region_writer.cpp.
/// `changes`, when given, bounds where the write can change anything (cut_history.hpp): only
/// leaves near it are visited.
double writeRegion(StockGrid& stock, const RevolvedRegion& region, RegionWrite how,
                   const RevolvedRegion* changes = nullptr);
double writeRegion(StockGrid& stock, const HelicalSweep& sweep, RegionWrite how,
                   const ThreadChangeBound* changes = nullptr);
double writeRegion(StockGrid& stock, const StraightSlot& slot, RegionWrite how);

/// Bytes the level set of the stock's bar takes, estimated from its surface (stock.cpp).
std::uint64_t estimatedBarBytes(const StockSpec& spec, double voxelMm);

}  // namespace lathesim::sim
