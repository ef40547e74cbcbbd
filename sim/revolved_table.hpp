#pragma once
// Inside sim only: the stock while it is still a solid of revolution, as a table of values by
// radius class and Z rather than voxel by voxel.
//
// While only revolved regions have been written (the bar or tube, then turning cuts), every
// voxel's value is the same function of its (ρ, z): voxels (i, j, k) and (i', j', k) with
// i² + j² = i'² + j'² went through the same writes with the same distances. The table keeps one
// value per class of equal i² + j² (Φ50 at 0.1 mm: about 16,000 classes for 200,000 columns,
// some thirteen columns a class) and Z, and writes a revolved region there with the level set's
// own column write (column_write.hpp): the same values, active bits and ghost candidates, each
// class's lost material counted as many times as it has columns. A turning move then costs its
// changed cells, not its voxels and no tree edits; the level set is written from the table
// only when something reads it (stock.cpp).
//
// A ghost (region_writer.cpp, step 4) is decided by a voxel's 26 neighbours, and columns of one
// class can have neighbours of different classes: the table asks each of the class's columns
// up to symmetry. When they disagree, the voxels found ghosts become *air voxels*: kept apart,
// air whatever their class's cell says. That cell is then not material (a ghost candidate lies
// above the material ceiling) and later removals only raise it, so it stays not material: no
// ghost verdict of a neighbour changes, and an air voxel is air for good. The table stays the
// stock, voxel for voxel as the level set's writer would leave it (seed 000 makes 324 such
// voxels in one write), and its volume counts them once.

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "geometry/revolved_region.hpp"

namespace lathesim::sim {

/// The table's cells are kept and written in chunks of this many along Z: one leaf's column
/// of the level set, so a chunk maps to whole leaves.
inline constexpr int kChunk = RevolvedRegion::kColumn;
static_assert(kChunk == 8);

/// A voxel of the level set by index.
struct VoxelIndex {
  int i, j, k;
};

/// A box of samples of the meridian plane (the voxels (i, 0, k), i ≥ 0): i from iLow to iHigh,
/// k from kLow to kHigh; empty until a sample is added (an empty box is always the default
/// one, so two boxes are equal when their bounds are).
struct MeridianBox {
  int iLow = INT_MAX, iHigh = INT_MIN, kLow = INT_MAX, kHigh = INT_MIN;
  bool empty() const { return iLow > iHigh; }
  bool operator==(const MeridianBox&) const = default;
  void add(int i, int k) {
    iLow = std::min(iLow, i), iHigh = std::max(iHigh, i), kLow = std::min(kLow, k), kHigh = std::max(kHigh, k);
  }
  void add(const MeridianBox& other) {
    if (other.empty()) return;
    add(other.iLow, other.kLow);
    add(other.iHigh, other.kHigh);
  }
};

class RevolvedTable {
 public:
  /// The columns −halfWidth…halfWidth in X and Y, Z from kFirst to kLast (voxel indices),
  /// all starting at φ = `bandMm` (air). Columns farther from the axis than `airRadiusMm` are
  /// taken never to change (nothing reaches them: the caller's promise).
  RevolvedTable(int halfWidth, int kFirst, int kLast, double voxelMm, float bandMm, double airRadiusMm);

  /// Bytes the table takes now (its chunks and indices; what the allocator adds aside).
  std::uint64_t bytes() const;

  /// How big a write must be before its work is shared among threads: `work` its classes by
  /// the chunks of its box (what it writes at most: which chunks the change bound reaches is
  /// asked by the threads themselves), `verdicts` its ghost verdicts (one per orbit of a ghost candidate's
  /// class). Below them the calling thread does it alone: waking another and waiting for it
  /// costs more. Measured on a CAM contour's 0.03 mm steps (wall time, both cores free): 1.8 s
  /// all on one thread, 1.2 s from 500 to 5,000, and more CPU time the lower the threshold.
  /// Either route gives the same table to the last bit; tests force each.
  struct ParallelThresholds {
    std::size_t work = 4000;
    std::size_t verdicts = 2000;
    /// Every write shared among threads, however small; or none, however large.
    static ParallelThresholds always() { return {0, 0}; }
    static ParallelThresholds never() { return {SIZE_MAX, SIZE_MAX}; }
  };
  void setParallelThresholds(const ParallelThresholds& thresholds) { parallel_ = thresholds; }

  /// Writes the revolved `region`: adding (φ ← min(φ, ψ)) or removing (φ ← max(φ, −ψ)).
  /// `changes`, when given, bounds where the write can change anything (cut_history.hpp).
  /// Returns the material voxels lost (negative when added).
  double write(const RevolvedRegion& region, bool adding, const RevolvedRegion* changes = nullptr);

  /// The value and active bit of voxel (i, j, k): those of its class (air for an air voxel), or
  /// air beyond the table.
  float value(int i, int j, int k) const;
  bool active(int i, int j, int k) const;
  /// value(i, j, k) for k = kFirst … kFirst + count − 1, into out[0], out[stride], …: a column
  /// read a chunk at a time rather than voxel by voxel.
  void columnValues(int i, int j, int kFirst, int count, float* out, std::size_t stride) const;

  /// The eight cells of column (i, j)'s class from Z index k0 (a multiple of 8) and their
  /// active bits; nullptr for a column that is always air (beyond the table or its air radius).
  /// Air voxels are not applied: see applyAirVoxels.
  const float* column(int i, int j, int k0, std::uint8_t& activeBits) const;
  /// Makes the air voxels of the 8³ leaf at `origin` air in its image: `values` and
  /// `activeBits` laid out as OpenVDB's leaf ((i << 6) | (j << 3) | k; a byte per column).
  void applyAirVoxels(const VoxelIndex& origin, float* values, std::uint8_t* activeBits) const;
  /// How many air voxels there are (each kept apart: see the top of this file).
  std::size_t airVoxelCount() const { return airVoxels_.size(); }

  /// The samples of the meridian plane (voxels (i, 0, k), i ≥ 0) that turned from material
  /// (φ < 0) to air since the last call, boxed; then forgotten. Nothing else changes how the
  /// section's material hangs together (loose_pieces.cpp): a removal only ever raises φ.
  MeridianBox takeMeridianFlips() { return std::exchange(meridianFlips_, MeridianBox{}); }

  /// The origins of the 8³ leaf-aligned blocks of voxels in which some value or active bit
  /// changed since the last call (which are then forgotten).
  std::vector<VoxelIndex> changedLeaves();
  /// Forgets what changed (the level set was written the same way already).
  void forgetChanges();

  // Read access for the mesh drawn from the table's profile (profile_mesh.cpp): the classes
  // in ascending ρ, each a column of cells along Z in chunks of 8 (one leaf's column). Air
  // voxels are not in it: each is one column of its class at one Z, at most a voxel off the
  // surface, and not material either way.
  int classCount() const { return static_cast<int>(rho_.size()); }
  /// ρ of class c's columns (mm).
  double classRadiusMm(int c) const { return rho_[c]; }
  /// Z index of the first cell; each class has chunkCount() chunks from there.
  int firstCellK() const { return kBase_; }
  int chunkCount() const { return chunks_; }
  /// The eight values of class c's chunk `chunk` (Z indices firstCellK() + 8·chunk …).
  const float* chunkCells(int c, int chunk) const {
    std::uint8_t bits;
    return cellsOf(c, chunk, bits);
  }
  /// Visits the mixed chunks of class c (those not one inactive value at ±band: the others
  /// are plain air or solid, and no surface passes within them; only these hold cells) in
  /// ascending Z: fn(k0, cells, activeBits) with k0 the Z index of the chunk's first cell.
  template <class Fn>
  void forEachMixedChunk(int c, Fn&& fn) const {
    const ClassChunks& row = classes_[c];
    const std::uint16_t* slots = &slots_[static_cast<std::size_t>(c) * chunks_];
    for (int chunk = 0; chunk < chunks_; ++chunk)
      if (slots[chunk] < kSolidChunk)
        fn(kBase_ + chunk * kChunkCells, row.pool[slots[chunk]].values, row.pool[slots[chunk]].activeBits);
  }

 private:
  static constexpr int kAir = -1;
  static constexpr int kChunkCells = 8;
  // Per class and chunk of 8 cells along Z (one leaf's column), two bytes: a tag when the chunk
  // is uniform (every cell the same inactive value: +band, air, or −band, solid), else the slot
  // of its cells in the class's pool. So the cells follow the band of the profile, and the
  // index costs 2 bytes a chunk, not 34 (OpenVDB's tiles, in one dimension).
  static constexpr std::uint16_t kAirChunk = 0xFFFF, kSolidChunk = 0xFFFE;

 public:
  /// The most chunks of 8 cells along Z a table can have.
  static constexpr int kMaxChunks = kSolidChunk;

 private:
  struct MixedChunk {
    float values[kChunkCells];
    std::uint8_t activeBits;
  };
  struct ClassChunks {
    std::vector<MixedChunk> pool;
    std::vector<std::uint16_t> freeSlots;
  };
  // The cells of one chunk while it is written: the pool's, or a copy of a uniform run's.
  struct ChunkCells {
    float* values;
    std::uint8_t* activeBits;
    std::uint16_t slot;
    float copy[kChunkCells];
    std::uint8_t copyBits;
  };

  // A write's working parts (revolved_table_write.cpp).
  struct WritePass;
  struct Candidates;
  struct Place;
  struct WriteScratch;
  struct Ghost;
  static WriteScratch& threadScratch();
  void reachedChunks(const WritePass& pass, double rhoMid, std::vector<int>& reached) const;
  void writeBinRange(WritePass& pass, std::size_t binBegin, std::size_t binEnd);
  void writeChunk(WritePass& pass, int c, const Place& place, std::vector<Candidates>& found, MeridianBox& flips);
  void clearGhosts(WritePass& pass, double& lost);
  void findGhosts(WritePass& pass, std::vector<Ghost>& ghosts, std::vector<std::pair<Ghost, VoxelIndex>>& airVoxels) const;

  int classOf(int i, int j) const;
  const float* cellsOf(int c, int chunk, std::uint8_t& activeBits) const;
  void open(int c, int chunk, ChunkCells& cells);
  void store(int c, int chunk, ChunkCells& cells);
  void markChanged(int c, int chunk) { changed_[static_cast<std::size_t>(c) * changedWords_ + chunk / 64] |= std::uint64_t{1} << (chunk % 64); }
  bool isChanged(int c, int chunk) const { return (changed_[static_cast<std::size_t>(c) * changedWords_ + chunk / 64] >> (chunk % 64)) & 1; }
  bool isGhost(int i, int j, int k, float material) const;
  // Adds to `flips` the cells of class c's chunk that turned from material to air (see
  // takeMeridianFlips); class c holds a column (i, 0) of the meridian plane.
  void noteFlips(int c, int chunk, const float* before, const float* after, MeridianBox& flips) const;
  // Whether class c's cell just below or above `cell` is material: then each of the class's
  // columns has a material neighbour there, and none of its voxels at `cell` is a ghost.
  bool materialAboveOrBelow(int c, int cell, float material) const;
  // Air voxels (see the top of this file).
  static std::uint64_t keyOf(int i, int j, int k);
  std::uint64_t cellKeyOf(int c, int cell) const { return static_cast<std::uint64_t>(c) * chunks_ * kChunkCells + cell; }
  int airVoxelsIn(int c, int cell) const;
  bool isAirVoxel(int c, int i, int j, int k) const { return classHasAirVoxels_[c] && airVoxels_.count(keyOf(i, j, k)); }
  void addAirVoxel(const VoxelIndex& v, int c, int cell);
  void dropAirVoxels(int c, int cell);

  ParallelThresholds parallel_;
  int halfWidth_;
  int kBase_;    // Z index of the first cell: a multiple of 8, as the level set's leaves
  int chunks_;   // Z chunks of 8 cells per class
  double h_;
  float band_;
  float airCells_[kChunkCells], solidCells_[kChunkCells];  // a uniform run's cells
  std::vector<int> classOfColumn_;        // (i + halfWidth)·(2·halfWidth + 1) + j + halfWidth → class or kAir
  std::vector<std::int64_t> sumOfSquares_;  // per class, ascending: i² + j²
  std::vector<double> rho_;               // per class: ρ of its widest column (i, j), i ≥ j ≥ 0, j least
  std::vector<int> binFirst_;             // per bin of classes one voxel wide in ρ: its first class; then the class count
  std::vector<int> binOfClass_;           // per class: its bin
  std::vector<double> columns_;           // per class: how many columns it has
  std::vector<int> meridianColumn_;       // per class: i of its column (i, 0), or −1 when it has none
  MeridianBox meridianFlips_;             // see takeMeridianFlips
  std::vector<int> orbitStart_;           // per class: its columns up to symmetry, orbits_[start…next)
  std::vector<std::pair<int, int>> orbits_;  // (i, j) with i ≥ j ≥ 0
  std::vector<ClassChunks> classes_;
  std::vector<std::uint16_t> slots_;      // per class, per chunk: kAirChunk, kSolidChunk or a slot in its pool
  int changedWords_;                      // per class: chunks changed since changedLeaves(), a bit each
  std::vector<std::uint64_t> changed_;
  int changedClassLow_ = 0, changedClassHigh_ = -1, changedChunkLow_ = 0, changedChunkHigh_ = -1;
  std::unordered_set<std::uint64_t> airVoxels_;                      // keyOf(i, j, k)
  std::unordered_map<std::uint64_t, int> airVoxelsInCell_;           // cellKeyOf(c, cell) → how many
  std::unordered_map<std::uint64_t, std::vector<VoxelIndex>> airVoxelsInLeaf_;  // keyOf(leaf origin) → its
  std::vector<std::uint8_t> classHasAirVoxels_;                      // per class
};

}  // namespace lathesim::sim
