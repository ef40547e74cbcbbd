#pragma once
// The stock as a narrow-band level set. OpenVDB stays behind this interface (compiling a
// FloatGrid costs seconds and gigabytes per translation unit), so callers see plain types.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>

#include <Eigen/Core>
#include <string>

#include "geometry/helical_sweep.hpp"
#include "geometry/meridian_profile.hpp"
#include "geometry/revolved_region.hpp"
#include "geometry/straight_slot.hpp"
#include "geometry/triangle_mesh.hpp"
#include "sim/stock_spec.hpp"
#include "sim/thread_history.hpp"

namespace lathesim::sim {

struct StockGrid;  // the OpenVDB side, in stock_grid.hpp

/// Narrow band half-width, in voxels, on each side of the surface.
inline constexpr int kHalfBandVoxels = 3;

/// How far a volume measured on the level set, or on its mesh, may stray from the exact
/// volume of the solid it stands for: 5 % of one voxel layer over the solid's surface. The
/// level set places the surface to a small fraction of a voxel, so its rounding is a thin
/// skin; a real error (a cut misplaced by a voxel, a block of material lost) moves whole
/// voxel layers over part of the surface.
inline constexpr double kVolumeToleranceVoxelLayers = 0.05;
inline double volumeToleranceMm3(double surfaceAreaMm2, double voxelMm) {
  return kVolumeToleranceVoxelLayers * voxelMm * surfaceAreaMm2;
}

/// Memory the stock's level set is expected to take at this voxel size (bytes), from its
/// surface area and a per-surface-voxel cost measured on this machine.
std::uint64_t estimatedStockBytes(const StockSpec& spec, double voxelMm);

/// Why a grid cannot be simulated here (too large for memory, bad voxel), or nullopt.
std::optional<std::string> gridProblem(const StockSpec& spec, double voxelMm);

/// Where a write can have changed the stock, in the meridian half-plane (mm): radii and Z that
/// hold what was written (a thread's or a slot's revolved hull, for those).
struct ChangedArea {
  double rhoMin = 0, rhoMax = 0, zMin = 0, zMax = 0;

  static ChangedArea of(const RevolvedRegion& region) {
    return {std::max(region.lowerBound().x(), 0.0), region.maxRadius(), region.lowerBound().y(),
            region.upperBound().y()};
  }
  void add(const ChangedArea& other) {
    rhoMin = std::min(rhoMin, other.rhoMin);
    rhoMax = std::max(rhoMax, other.rhoMax);
    zMin = std::min(zMin, other.zMin);
    zMax = std::max(zMax, other.zMax);
  }
};

/// How turning cuts are written while the stock is still a solid of revolution: into a table
/// by radius and Z, the level set written from it only when something reads it (the default:
/// a move then costs what it changes in the meridian plane), or straight into the level set
/// voxel by voxel (what the table must agree with; for tests). Both give the same stock.
enum class RevolvedWrites { Table, Voxels };

class Stock {
 public:
  /// Builds the bar from its analytic distance: into the revolved table (RevolvedWrites::Table,
  /// when the table is small beside the level set), the level set then built from it when
  /// first read; or into the level set, leaf by leaf.
  Stock(const StockSpec& spec, double voxelMm, RevolvedWrites writes = RevolvedWrites::Table);
  ~Stock();
  Stock(const Stock&) = delete;
  Stock& operator=(const Stock&) = delete;

  double voxelMm() const;
  /// The bar it was made from (a piece taken out of it keeps its bar's).
  const StockSpec& spec() const;

  /// Removes the solid of revolution of `region`: φ ← max(φ, −ψ). Only leaves near both the
  /// region's boundary and the material are visited. Returns the volume removed (mm³),
  /// measured on the level set before and after.
  double remove(const RevolvedRegion& region);
  /// The same, visiting only leaves near `changes`, outside whose band the caller vouches that
  /// this write changes nothing (CutHistory::changesOf): the same result, at the cost of what
  /// changes rather than of the region's whole outline.
  double remove(const RevolvedRegion& region, const RevolvedRegion& changes);
  /// The same for a thread pass (helical_sweep.hpp) and for a cut made with the spindle
  /// stopped (straight_slot.hpp): written voxel by voxel with their own 3D distance, over the
  /// leaves near their revolved hull's boundary and the material.
  double remove(const HelicalSweep& sweep);
  double remove(const StraightSlot& slot);
  /// The thread pass again, visiting only leaves where `changes` (ThreadHistory::changesOf)
  /// says it can change anything: the same result, at the cost of what it changes.
  double remove(const HelicalSweep& sweep, const ThreadChangeBound& changes);

  /// Volume (mm³) of material lying deeper than `marginMm` inside the revolved `region`,
  /// measured without changing anything. It is integrated over the meridian half-plane: each
  /// voxel (ρ, 0, z) stands for its ring. Exact while the stock is a solid of revolution; a
  /// thread's grooves or a slot (cuts that are not) count as they lie at azimuth 0, an
  /// estimate of the holder's collision volume, which is all it serves. See stock_probe.cpp.
  double materialInside(const RevolvedRegion& region, double marginMm) const;

  /// Volume enclosed by the zero level set (mm³): each voxel counts the fraction
  /// clamp(½ − φ/h, 0, 1) of itself, and interior tiles count whole.
  double volumeMm3() const;

  /// φ at the point at radius ρ = point.x(), Z = point.y() (mm), trilinearly sampled:
  /// negative inside the material, positive outside; beyond the narrow band it is ±3 voxels.
  double signedDistanceAt(const RZ& point) const;
  /// φ at the point (x, y, z) of the part's frame (mm), trilinearly sampled: for what is not
  /// a solid of revolution (threads, slots cut with the spindle stopped).
  double signedDistanceAt(double xMm, double yMm, double zMm) const;
  /// The same at many points at once (one accessor for all): out[i] for points[i].
  void signedDistancesAt(std::span<const Eigen::Vector3d> points, std::span<double> out) const;

  /// Closed surface just inside φ = 0 (0.16 % of a voxel: see stock_grid.hpp), outward
  /// normals, vertices merged by position as an STL reader merges them. While the stock is
  /// revolved (isRevolved), its profile revolved about Z, to within a twentieth of a voxel,
  /// enclosing the profile's own volume (profile_mesh.cpp), its profile simplified (a straight
  /// face is one band of facets). Otherwise the level set's: adaptivity 0 keeps every voxel's
  /// facets; larger values (up to 1) merge facets on flat and gently curved areas.
  TriangleMesh mesh(double adaptivity) const;
  /// The same surface with a vertex about every voxel along it, for values carried by the
  /// vertices and blended between them (deviation.png's colours, which on a simplified face
  /// would blend its two ends' colours over a step the drawing has and the part lacks).
  TriangleMesh meshWithVertexEveryVoxel() const;
  /// Whether the stock is still a solid of revolution held by radius and Z (only turning cuts
  /// so far: a thread, a cut with the spindle stopped or a part-off ends it for good).
  bool isRevolved() const;
  /// The same surface (adaptivity 0) within the box x `low.x()`…`high.x()` × y … × z … (mm)
  /// only, closed by the box's faces where it cuts the material, and `subdivisions` (≥ 1)
  /// times finer than the voxels: φ sampled trilinearly near the surface on voxels that
  /// split each voxel k × k × k ways. That adds no detail the level set lacks; it draws its
  /// trilinear surface, where one facet a voxel shows as steps and saw edges once a voxel
  /// fills many pixels (a picture's close-up). Costs what the box holds, not the part.
  TriangleMesh mesh(const Eigen::Vector3d& low, const Eigen::Vector3d& high, int subdivisions) const;

  /// φ in the meridian plane y = 0, x ≥ 0, at every voxel centre over the bar's extent and
  /// a band's width beyond (see stock_outline.cpp).
  SampledSection meridianSection() const;

  /// Takes the material that no longer hangs together with the chuck's end out of this stock
  /// and returns it as a stock of its own, or nullptr when all material still does (see
  /// loose_pieces.cpp). The chuck's end is the material nearest the chuck: the lowest Z.
  /// `lastCut`, where the stock was written since the material last hung together (crumbs
  /// aside), lets it look only around there when the cut plainly parted nothing.
  /// `notRevolved`: the last cut was no solid of revolution (a slot cut with the spindle
  /// stopped, a helix), so the meridian section need not show what still holds: a piece the
  /// section sees loose is taken out only if the material is in more than one piece in 3D.
  std::unique_ptr<Stock> takeLoosePieces(const std::optional<ChangedArea>& lastCut = std::nullopt,
                                         bool notRevolved = false);

  /// Writes the level set (.vdb, half floats, Blosc-compressed) under the grid name "stock", and `part`'s
  /// (a piece taken out by takeLoosePieces) beside it under the name "part".
  void writeVdb(const std::filesystem::path& file, const Stock* part = nullptr) const;

  std::uint64_t activeVoxelCount() const;
  /// Bytes the stock holds now: its table while it is revolved, and its level set as far as it
  /// is built (it is built when first read: a mesh or a volume do not read it while revolved;
  /// stock.vdb, a thread or a slot do).
  std::uint64_t memoryBytes() const;

 private:
  explicit Stock(std::unique_ptr<StockGrid> grid);
  std::unique_ptr<StockGrid> impl_;
};

}  // namespace lathesim::sim
