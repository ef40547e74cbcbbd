#include "sim/revolved_table.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <utility>

#include "sim/column_write.hpp"

namespace lathesim::sim {
namespace {

constexpr int kChunk = RevolvedRegion::kColumn;  // 8 cells along Z: one leaf's column
static_assert(kChunk == 8);

int alignDown(int k) { return k & ~(kChunk - 1); }

// The largest i² + j² a column nearer the axis than airRadiusMm can have.
std::int64_t largestSumOfSquares(double airRadiusMm, double voxelMm) {
  const double cells = airRadiusMm / voxelMm;
  return static_cast<std::int64_t>(std::floor(cells * cells));
}

// How many columns the orbit of (i, j), i ≥ j ≥ 0, has under the square's symmetries.
int orbitSize(int i, int j) {
  if (i == 0) return 1;
  return j == 0 || j == i ? 4 : 8;
}

// A column of cells deep inside the region (ψ < −bg − h everywhere): writeColumn's result
// without the distances. Each open cell takes the filled value u = −bg and goes inactive.
// Returns the material voxels lost; sets `changed` when anything did.
double fill(float* values, std::uint8_t& activeBits, const ColumnWrite& w, bool& changed) {
  const float filled = static_cast<float>(w.sign * -w.band);
  const double filledShare = std::clamp(0.5 - filled * w.inverseVoxel, 0.0, 1.0);
  double lost = 0.0;
  for (int k = 0; k < kChunk; ++k) {
    if (!(w.sign * values[k] > -w.band)) continue;  // already as deep in the region's state as the band allows
    lost += std::clamp(0.5 - values[k] * w.inverseVoxel, 0.0, 1.0) - filledShare;
    values[k] = filled;
    activeBits &= static_cast<std::uint8_t>(~(1u << k));
    changed = true;
  }
  return lost;
}

// The material voxels a write lost, in class order: per class, its cell's loss times its
// columns less what its air voxels did not lose. Only classes that changed lost anything; the
// others' terms are +0, which leave the sum as it is to the bit. A function of its own, so that
// the sum stays in a register: inlined into the write, it was kept in memory, a store and a
// load an addition over thousands of classes a write (3 % of a CAM program).
[[gnu::noinline]] double lostVoxels(const std::vector<char>& changed, const std::vector<double>& lostOf,
                                    const std::vector<double>& airVoxelsLost, const double* columns) {
  double sum = 0.0;
  for (std::size_t n = 0; n < changed.size(); ++n)
    if (changed[n]) sum += lostOf[n] * columns[n] - airVoxelsLost[n];
  return sum;
}

// A chunk's ghost candidates (class n of the write's first, its chunk, a bit per cell),
// gathered by each task and then put in class and chunk order, the order in which a single
// thread would have found them. A task writes a range of bins in order, so its own candidates
// are in that order already: only the tasks' runs need ordering, by their first bins.
struct Candidates {
  int n, chunk;
  std::uint8_t bits;
};

// A chunk of a bin of classes as a write finds it (RevolvedTable::write).
struct Place {
  int chunk;
  bool covered;  // deep inside the region: every open cell is filled
  const RevolvedRegion* local;
  const RevolvedRegion::ColumnPlan* plan;  // or none
};

// What a task of a write needs while it writes its bins: the region near each of a bin's
// places and their plans (one per chunk of the write's box), the places, the ghost candidates
// found. Each thread keeps its own from write to write, so that their memory, the regions'
// edges too (RevolvedRegion::nearInto), is reused rather than allocated again every write. A
// task holds it only while it runs, and a task never waits for another.
struct WriteScratch {
  std::vector<RevolvedRegion> nearby;
  std::vector<RevolvedRegion::ColumnPlan> plans;
  std::vector<Place> places;
  std::vector<Candidates> found;
  std::vector<int> reached;  // chunks of the bin being written
};
thread_local WriteScratch scratch;

}  // namespace

RevolvedTable::RevolvedTable(int halfWidth, int kFirst, int kLast, double voxelMm, float bandMm, double airRadiusMm)
    : halfWidth_(halfWidth), kBase_(alignDown(kFirst)), chunks_((alignDown(kLast) - alignDown(kFirst)) / kChunk + 1),
      h_(voxelMm), band_(bandMm) {
  const std::int64_t nMax = largestSumOfSquares(airRadiusMm, voxelMm);
  const int side = 2 * halfWidth + 1;
  // Classes in ascending i² + j², so that a range of radii is a range of classes.
  std::vector<int> classOfSum(static_cast<std::size_t>(nMax) + 1, kAir);
  for (int i = 0; i <= halfWidth; ++i)
    for (int j = 0; j <= i; ++j) {
      const std::int64_t n = std::int64_t{i} * i + std::int64_t{j} * j;
      if (n <= nMax) classOfSum[n] = 0;
    }
  for (std::int64_t n = 0; n <= nMax; ++n)
    if (classOfSum[n] != kAir) {  // a sum of two squares within the air radius
      classOfSum[n] = static_cast<int>(sumOfSquares_.size());
      sumOfSquares_.push_back(n);
    }
  const int classes = static_cast<int>(sumOfSquares_.size());
  rho_.assign(classes, 0.0);
  columns_.assign(classes, 0.0);
  orbitStart_.assign(classes + 1, 0);
  meridianColumn_.assign(classes, -1);
  for (int i = 0; i <= halfWidth; ++i)
    for (int j = 0; j <= i; ++j) {
      const std::int64_t n = std::int64_t{i} * i + std::int64_t{j} * j;
      if (n <= nMax) ++orbitStart_[classOfSum[n] + 1];
    }
  for (int c = 0; c < classes; ++c) orbitStart_[c + 1] += orbitStart_[c];
  orbits_.resize(orbitStart_[classes]);
  std::vector<int> filled(orbitStart_.begin(), orbitStart_.end() - 1);
  for (int i = 0; i <= halfWidth; ++i)
    for (int j = 0; j <= i; ++j) {
      const std::int64_t n = std::int64_t{i} * i + std::int64_t{j} * j;
      if (n > nMax) continue;
      const int c = classOfSum[n];
      orbits_[filled[c]++] = {i, j};
      columns_[c] += orbitSize(i, j);
      if (j == 0) meridianColumn_[c] = i;
      // ρ as the level set's writer computes it for this column (its widest one, the last
      // found: j = 0 where the class has one, so that the meridian plane y = 0 reads exactly).
      const double x = i * h_, y = j * h_;
      rho_[c] = std::sqrt(x * x + y * y);
    }
  binOfClass_.resize(classes);
  for (int c = 0; c < classes; ++c) {
    if (c == 0 || std::floor(rho_[c] / h_) != std::floor(rho_[c - 1] / h_)) binFirst_.push_back(c);
    binOfClass_[c] = static_cast<int>(binFirst_.size()) - 1;
  }
  binFirst_.push_back(classes);
  classOfColumn_.assign(static_cast<std::size_t>(side) * side, kAir);
  for (int i = -halfWidth; i <= halfWidth; ++i)
    for (int j = -halfWidth; j <= halfWidth; ++j) {
      const std::int64_t n = std::int64_t{i} * i + std::int64_t{j} * j;
      if (n <= nMax) classOfColumn_[static_cast<std::size_t>(i + halfWidth) * side + (j + halfWidth)] = classOfSum[n];
    }
  std::fill_n(airCells_, kChunk, bandMm);
  std::fill_n(solidCells_, kChunk, -bandMm);
  classes_.resize(classes);
  classHasAirVoxels_.assign(classes, 0);
  slots_.assign(static_cast<std::size_t>(classes) * chunks_, kAirChunk);
  changedWords_ = (chunks_ + 63) / 64;
  changed_.assign(static_cast<std::size_t>(classes) * changedWords_, 0);
}

std::uint64_t RevolvedTable::bytes() const {
  std::uint64_t total = sizeof *this + classes_.capacity() * sizeof(ClassChunks) + slots_.capacity() * sizeof(std::uint16_t) + changed_.capacity() * sizeof(std::uint64_t) +
                        classOfColumn_.capacity() * sizeof(int) + sumOfSquares_.capacity() * sizeof(std::int64_t) +
                        (rho_.capacity() + columns_.capacity()) * sizeof(double) +
                        (orbitStart_.capacity() + binFirst_.capacity() + binOfClass_.capacity() + meridianColumn_.capacity()) * sizeof(int) +
                        orbits_.capacity() * sizeof(orbits_[0]);
  for (const ClassChunks& row : classes_)
    total += row.pool.capacity() * sizeof(MixedChunk) + row.freeSlots.capacity() * sizeof(std::uint16_t);
  return total;
}

const float* RevolvedTable::cellsOf(int c, int chunk, std::uint8_t& activeBits) const {
  const std::uint16_t slot = slots_[static_cast<std::size_t>(c) * chunks_ + chunk];
  if (slot < kSolidChunk) {
    const MixedChunk& mixed = classes_[c].pool[slot];
    activeBits = mixed.activeBits;
    return mixed.values;
  }
  activeBits = 0;
  return slot == kAirChunk ? airCells_ : solidCells_;
}

void RevolvedTable::open(int c, int chunk, ChunkCells& cells) {
  cells.slot = slots_[static_cast<std::size_t>(c) * chunks_ + chunk];
  if (cells.slot < kSolidChunk) {
    MixedChunk& mixed = classes_[c].pool[cells.slot];
    cells.values = mixed.values;
    cells.activeBits = &mixed.activeBits;
    return;
  }
  std::fill_n(cells.copy, kChunk, cells.slot == kAirChunk ? band_ : -band_);
  cells.copyBits = 0;
  cells.values = cells.copy;
  cells.activeBits = &cells.copyBits;
}

void RevolvedTable::store(int c, int chunk, ChunkCells& cells) {
  // Most often: a chunk of the pool, written in place, with an active cell (so not uniform).
  if (cells.slot < kSolidChunk && *cells.activeBits != 0) return;
  ClassChunks& row = classes_[c];
  std::uint16_t& slot = slots_[static_cast<std::size_t>(c) * chunks_ + chunk];
  const float first = cells.values[0];
  bool uniform = *cells.activeBits == 0 && (first == band_ || first == -band_);
  for (int k = 1; k < kChunk && uniform; ++k) uniform = cells.values[k] == first;
  if (uniform) {
    if (slot < kSolidChunk) row.freeSlots.push_back(slot);  // the chunk is a tag again
    slot = first == band_ ? kAirChunk : kSolidChunk;
    return;
  }
  if (slot < kSolidChunk) return;  // written in place
  if (!row.freeSlots.empty()) {
    slot = row.freeSlots.back();
    row.freeSlots.pop_back();
  } else {
    slot = static_cast<std::uint16_t>(row.pool.size());
    row.pool.emplace_back();
  }
  std::memcpy(row.pool[slot].values, cells.values, sizeof cells.copy);
  row.pool[slot].activeBits = *cells.activeBits;
}

int RevolvedTable::classOf(int i, int j) const {
  if (i < -halfWidth_ || i > halfWidth_ || j < -halfWidth_ || j > halfWidth_) return kAir;
  return classOfColumn_[static_cast<std::size_t>(i + halfWidth_) * (2 * halfWidth_ + 1) + (j + halfWidth_)];
}

float RevolvedTable::value(int i, int j, int k) const {
  const int c = classOf(i, j);
  const int cell = k - kBase_;
  if (c == kAir || cell < 0 || cell >= chunks_ * kChunk) return band_;
  if (isAirVoxel(c, i, j, k)) return band_;
  std::uint8_t bits;
  return cellsOf(c, cell / kChunk, bits)[cell % kChunk];
}

void RevolvedTable::columnValues(int i, int j, int kFirst, int count, float* out, std::size_t stride) const {
  const int c = classOf(i, j);
  const bool hasAirVoxels = c != kAir && classHasAirVoxels_[c];
  int chunk = -1;
  const float* cells = nullptr;
  for (int n = 0; n < count; ++n) {
    const int k = kFirst + n, cell = k - kBase_;
    float v = band_;
    if (c != kAir && cell >= 0 && cell < chunks_ * kChunk) {
      if (cell / kChunk != chunk) {
        chunk = cell / kChunk;
        std::uint8_t bits;
        cells = cellsOf(c, chunk, bits);
      }
      v = hasAirVoxels && airVoxels_.count(keyOf(i, j, k)) ? band_ : cells[cell % kChunk];
    }
    out[n * stride] = v;
  }
}

bool RevolvedTable::active(int i, int j, int k) const {
  const int c = classOf(i, j);
  const int cell = k - kBase_;
  if (c == kAir || cell < 0 || cell >= chunks_ * kChunk) return false;
  if (isAirVoxel(c, i, j, k)) return false;
  std::uint8_t bits;
  cellsOf(c, cell / kChunk, bits);
  return (bits >> (cell % kChunk)) & 1;
}

std::uint64_t RevolvedTable::keyOf(int i, int j, int k) {
  // 21 bits for i and j, 22 for k: a stock spans at most a million voxels (stock.cpp).
  return (static_cast<std::uint64_t>(i + (1 << 20)) << 43) | (static_cast<std::uint64_t>(j + (1 << 20)) << 22) |
         static_cast<std::uint64_t>(k + (1 << 21));
}

int RevolvedTable::airVoxelsIn(int c, int cell) const {
  if (!classHasAirVoxels_[c]) return 0;
  const auto found = airVoxelsInCell_.find(cellKeyOf(c, cell));
  return found == airVoxelsInCell_.end() ? 0 : found->second;
}

void RevolvedTable::addAirVoxel(const VoxelIndex& v, int c, int cell) {
  if (!airVoxels_.insert(keyOf(v.i, v.j, v.k)).second) return;
  ++airVoxelsInCell_[cellKeyOf(c, cell)];
  airVoxelsInLeaf_[keyOf(v.i & ~(kChunk - 1), v.j & ~(kChunk - 1), v.k & ~(kChunk - 1))].push_back(v);
  classHasAirVoxels_[c] = 1;
}

// The class's cell is air now: its air voxels are air as it is.
void RevolvedTable::dropAirVoxels(int c, int cell) {
  if (airVoxelsInCell_.erase(cellKeyOf(c, cell)) == 0) return;
  const int k = kBase_ + cell;
  for (int o = orbitStart_[c]; o < orbitStart_[c + 1]; ++o)
    for (const auto& [x, y] : {orbits_[o], std::pair{orbits_[o].second, orbits_[o].first}})
      for (const int sx : {1, -1})
        for (const int sy : {1, -1}) {
          const int i = sx * x, j = sy * y;
          if (airVoxels_.erase(keyOf(i, j, k)) == 0) continue;
          auto leaf = airVoxelsInLeaf_.find(keyOf(i & ~(kChunk - 1), j & ~(kChunk - 1), k & ~(kChunk - 1)));
          std::erase_if(leaf->second, [&](const VoxelIndex& v) { return v.i == i && v.j == j && v.k == k; });
          if (leaf->second.empty()) airVoxelsInLeaf_.erase(leaf);
        }
}

void RevolvedTable::applyAirVoxels(const VoxelIndex& origin, float* values, std::uint8_t* activeBits) const {
  if (airVoxelsInLeaf_.empty()) return;
  const auto found = airVoxelsInLeaf_.find(keyOf(origin.i, origin.j, origin.k));
  if (found == airVoxelsInLeaf_.end()) return;
  for (const VoxelIndex& v : found->second) {
    const int column = ((v.i - origin.i) << 6) | ((v.j - origin.j) << 3);
    values[column + (v.k - origin.k)] = band_;
    activeBits[column >> 3] &= static_cast<std::uint8_t>(~(1u << (v.k - origin.k)));
  }
}

const float* RevolvedTable::column(int i, int j, int k0, std::uint8_t& activeBits) const {
  const int c = classOf(i, j);
  const int chunk = (k0 - kBase_) / kChunk;
  if (c == kAir || k0 < kBase_ || chunk >= chunks_) return nullptr;
  return cellsOf(c, chunk, activeBits);
}

bool RevolvedTable::isGhost(int i, int j, int k, float material) const {
  // Air never counts as material: only the neighbouring columns in the table are read, a
  // chunk at a time.
  const int cellLow = k - 1 - kBase_, cellHigh = k + 1 - kBase_;
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj) {
      const int c = classOf(i + di, j + dj);
      if (c == kAir) continue;
      int chunk = -1;
      const float* values = nullptr;
      std::uint8_t bits;
      for (int cell = std::max(0, cellLow); cell <= std::min(cellHigh, chunks_ * kChunk - 1); ++cell) {
        if ((di || dj || cell != k - kBase_) == false) continue;
        if (cell / kChunk != chunk) {
          chunk = cell / kChunk;
          values = cellsOf(c, chunk, bits);
        }
        if (values[cell % kChunk] <= material) return false;
      }
    }
  return true;
}

bool RevolvedTable::materialAboveOrBelow(int c, int cell, float material) const {
  for (const int next : {cell - 1, cell + 1}) {
    if (next < 0 || next >= chunks_ * kChunk) continue;
    std::uint8_t bits;
    if (cellsOf(c, next / kChunk, bits)[next % kChunk] <= material) return true;
  }
  return false;
}

void RevolvedTable::noteFlips(int c, int chunk, const float* before, const float* after, MeridianBox& flips) const {
  const int i = meridianColumn_[c];
  for (int cell = 0; cell < kChunk; ++cell) {
    const int k = kBase_ + chunk * kChunk + cell;
    if (before[cell] < 0.0f && after[cell] >= 0.0f && !isAirVoxel(c, i, 0, k)) flips.add(i, k);
  }
}

double RevolvedTable::write(const RevolvedRegion& region, bool adding, const RevolvedRegion* changes) {
  if (region.empty() || (changes && changes->empty()) || rho_.empty()) return 0.0;
  const ColumnWrite w = ColumnWrite::of(adding ? 1.0 : -1.0, h_, band_);
  // A cell changes only where ψ < bg, and is a ghost candidate only where |ψ| < h.
  const double reach = band_ + h_;
  double rhoLow = std::max(0.0, region.lowerBound().x()) - reach, rhoHigh = region.maxRadius() + reach;
  double zLow = region.lowerBound().y() - reach, zHigh = region.upperBound().y() + reach;
  // With a change bound, within its band, and a ghost's reach beyond (region_writer.cpp).
  const double changeMargin = band_ + 2.0 * h_;
  if (changes) {
    rhoLow = std::max(rhoLow, std::max(0.0, changes->lowerBound().x()) - changeMargin - h_);
    rhoHigh = std::min(rhoHigh, changes->maxRadius() + changeMargin + h_);
    zLow = std::max(zLow, changes->lowerBound().y() - changeMargin - h_);
    zHigh = std::min(zHigh, changes->upperBound().y() + changeMargin + h_);
  }
  const int classLow = static_cast<int>(std::lower_bound(rho_.begin(), rho_.end(), rhoLow) - rho_.begin());
  const int classHigh = static_cast<int>(std::upper_bound(rho_.begin(), rho_.end(), rhoHigh) - rho_.begin()) - 1;
  const int chunkLow = std::max(0, static_cast<int>(std::floor((zLow / h_ - kBase_) / kChunk)));
  const int chunkHigh = std::min(chunks_ - 1, static_cast<int>(std::floor((zHigh / h_ - kBase_) / kChunk)));
  if (classLow > classHigh || chunkLow > chunkHigh) return 0.0;

  const int classCount = classHigh - classLow + 1;
  std::vector<double> lostOf(classCount, 0.0);
  // Air voxels lost nothing when their class's cell did: per class, voxels to take back.
  std::vector<double> airVoxelsLost(classCount, 0.0);
  std::vector<Candidates> ghostCandidates;
  struct Run {
    std::size_t firstBin, start, size;  // a task's candidates: ghostCandidates[start, start + size)
  };
  std::vector<Run> ghostRuns;
  std::mutex ghostCandidatesMutex;
  std::vector<char> changedClass(classCount, 0);
  // Classes come in bins one voxel wide in ρ (at 22 mm about a hundred classes a bin): what
  // depends on the place only — whether the change bound reaches it, the region near it
  // (RevolvedRegion::nearInto, as the writer takes it per leaf: only the pieces and edges that
  // can be nearest there), whether the region is far or covers it — is asked once per bin and
  // chunk, for a place half a voxel wider. Then the bin's classes are written one after
  // another, each along its chunks: a class's slots and cells lie together in memory.
  std::vector<int> binStart{classLow};
  for (int bin = binOfClass_[classLow] + 1; bin <= binOfClass_[classHigh]; ++bin) binStart.push_back(binFirst_[bin]);
  binStart.push_back(classHigh + 1);
  const double binHalfWidth = 0.5 * h_;
  const double placeRadius = 0.5 * kChunk * h_ + binHalfWidth + reach;
  const double changeReach = binHalfWidth + changeMargin;
  const double cellReach = std::hypot(0.5 * (kChunk - 1) * h_, binHalfWidth);
  const double farReach = cellReach + band_ + h_;
  // A bin of this many classes or more reads the region through a plan of its place (see
  // RevolvedRegion::planColumn): one edge a piece and cell rather than all of them.
  constexpr int kPlannedClasses = 4;
  // The chunks of a bin that the change bound reaches (every chunk of the box without one):
  // a group of chunks at a time, then at each chunk's own cells rather than its centre (a
  // chunk is 8 voxels tall, and a move's sliver of change is often thinner than that). A
  // tool's flanks leave slivers along their whole length, so the box is often wide and the
  // bound reaches a few of its places. Asked by the task that writes the bin.
  constexpr int kGroup = 8;
  const auto reachedChunks = [&](double rhoMid, std::vector<int>& reached) {
    reached.clear();
    for (int group = chunkLow; group <= chunkHigh; group += kGroup) {
      const int groupEnd = std::min(chunkHigh + 1, group + kGroup);
      if (changes) {
        const double halfHeight = 0.5 * ((groupEnd - group) * kChunk - 1) * h_;
        const double zMid = (kBase_ + group * kChunk) * h_ + halfHeight;
        if (changes->signedDistance(rhoMid, zMid, halfHeight + changeReach + h_) > halfHeight + changeReach) continue;
      }
      for (int chunk = group; chunk < groupEnd; ++chunk) {
        if (changes) {
          double toChanges[kChunk];
          changes->signedDistanceColumn(rhoMid, (kBase_ + chunk * kChunk) * h_, h_, changeReach + h_, toChanges);
          if (*std::min_element(toChanges, toChanges + kChunk) > changeReach) continue;
        }
        reached.push_back(chunk);
      }
    }
  };
  const int binCount = static_cast<int>(binStart.size()) - 1;

  const auto writeBins = [&](const tbb::blocked_range<std::size_t>& range) {
    WriteScratch& mine = scratch;
    const std::size_t boxChunks = chunkHigh - chunkLow + 1;
    if (mine.nearby.size() < boxChunks) mine.nearby.resize(boxChunks);
    if (mine.plans.size() < boxChunks) mine.plans.resize(boxChunks);
    std::vector<RevolvedRegion>& nearby = mine.nearby;
    std::vector<RevolvedRegion::ColumnPlan>& plans = mine.plans;
    std::vector<Place>& places = mine.places;
    std::vector<Candidates>& found = mine.found;
    found.clear();
    MeridianBox flips;  // removals only: an addition turns no material to air
    for (std::size_t bin = range.begin(); bin != range.end(); ++bin) {
      const int first = binStart[bin], last = binStart[bin + 1];
      const double rhoMid = (std::floor(rho_[first] / h_) + 0.5) * h_;
      places.clear();
      reachedChunks(rhoMid, mine.reached);
      for (const int chunk : mine.reached) {
        const int k0 = kBase_ + chunk * kChunk;
        RevolvedRegion* const local = &nearby[chunk - chunkLow];
        region.nearInto(rhoMid, (k0 + 0.5 * kChunk) * h_, placeRadius, *local);
        if (local->empty()) continue;
        // The region's distance changes by at most the distance moved (each piece's is
        // 1-Lipschitz, inside and out, and so is their minimum): from the place's centre to
        // its cells, at most cellReach. Beyond reach nothing changes and nothing is a ghost
        // candidate; deep inside, every open cell is filled, as writeColumn would fill it.
        const double centre = local->signedDistance(rhoMid, (k0 + 0.5 * (kChunk - 1)) * h_, farReach + h_);
        if (centre > farReach) continue;
        const bool covered = centre < -farReach;
        RevolvedRegion::ColumnPlan* plan = nullptr;
        if (!covered && last - first >= kPlannedClasses) {
          plan = &plans[chunk - chunkLow];
          local->planColumn(rho_[first], rho_[last - 1], k0 * h_, h_, *plan);
        }
        places.push_back({chunk, covered, local, plan});
      }
      for (int c = first; c < last; ++c) {
        const int n = c - classLow;
        const bool onMeridian = !adding && meridianColumn_[c] >= 0;  // its turning to air is noted
        if (!places.empty() && c + 1 < last) {
          // The next classes' table lies elsewhere in memory: ask for it while this one is
          // written (their slots two ahead, the cells of the next one's first chunk).
          const int chunk = places.front().chunk;
          if (c + 2 < last) __builtin_prefetch(&slots_[static_cast<std::size_t>(c + 2) * chunks_ + chunk]);
          const std::uint16_t slot = slots_[static_cast<std::size_t>(c + 1) * chunks_ + chunk];
          if (slot < kSolidChunk) __builtin_prefetch(&classes_[c + 1].pool[slot]);
        }
        for (const auto& [chunk, covered, local, plan] : places) {
          const int k0 = kBase_ + chunk * kChunk;
          std::uint16_t& slot = slots_[static_cast<std::size_t>(c) * chunks_ + chunk];
          // Uniform and already as deep in the region's state as the band allows (air for a
          // removal, solid for an addition): no cell is open, nothing to read or write.
          if (slot == (adding ? kSolidChunk : kAirChunk)) continue;
          if (covered) {  // a uniform chunk turns over whole: what fill() would do, without its cells
            if (slot == (adding ? kAirChunk : kSolidChunk)) {  // no air voxels: they are in mixed chunks
              if (onMeridian) noteFlips(c, chunk, solidCells_, airCells_, flips);
              slot = adding ? kSolidChunk : kAirChunk;
              lostOf[n] += adding ? -kChunk : kChunk;
              markChanged(c, chunk);
              changedClass[n] = 1;
              continue;
            }
          }
          ChunkCells cells;
          open(c, chunk, cells);
          float* values = cells.values;
          float before[kChunk];
          std::memcpy(before, values, sizeof before);
          const auto takeBackAirVoxels = [&] {
            if (!classHasAirVoxels_[c]) return;
            for (int k = 0; k < kChunk; ++k)
              if (const int air = airVoxelsIn(c, chunk * kChunk + k))
                airVoxelsLost[n] += air * (std::clamp(0.5 - before[k] * w.inverseVoxel, 0.0, 1.0) -
                                           std::clamp(0.5 - values[k] * w.inverseVoxel, 0.0, 1.0));
          };
          if (covered) {
            bool changed = false;
            lostOf[n] += fill(values, *cells.activeBits, w, changed);
            if (changed) {
              if (onMeridian) noteFlips(c, chunk, before, values, flips);
              takeBackAirVoxels();
              markChanged(c, chunk);
              changedClass[n] = 1;
              store(c, chunk, cells);
            }
            continue;
          }
          // Some cell is open, no need to ask: a pooled chunk with none would be uniform at the
          // band's value, which store() makes a tag (passed over above), and the other tag's
          // cells (solid for a removal, air for an addition) are all open.
          double psi[kChunk];
          if (plan) local->signedDistanceColumn(*plan, rho_[c], band_, psi);
          else local->signedDistanceColumn(rho_[c], k0 * h_, h_, band_, psi);
          std::uint8_t& active = *cells.activeBits;
          const std::uint8_t activeBefore = active;
          std::uint8_t ghostBits = 0;
          lostOf[n] += writeColumn(w, values, psi, active, ghostBits);
          if (std::memcmp(before, values, sizeof before) != 0 || active != activeBefore) {
            if (onMeridian) noteFlips(c, chunk, before, values, flips);
            takeBackAirVoxels();
            markChanged(c, chunk);
            changedClass[n] = 1;
            store(c, chunk, cells);
          }
          if (ghostBits && !adding) {
            // A candidate with material just above or below it in this chunk is no ghost
            // (materialAboveOrBelow, asked here rather than after the write: this write does
            // not come back to the chunk, so its cells are final). Only the chunk's end cells
            // need the chunks beside it.
            std::uint8_t material = 0;
            for (int k = 0; k < kChunk; ++k) material |= static_cast<std::uint8_t>((values[k] <= w.notMaterial) << k);
            ghostBits &= static_cast<std::uint8_t>(~((material << 1) | (material >> 1)));
            if (ghostBits) found.push_back({n, chunk, ghostBits});
          }
        }
      }
    }
    if (found.empty() && flips.empty()) return;
    const std::lock_guard<std::mutex> lock(ghostCandidatesMutex);
    meridianFlips_.add(flips);
    if (found.empty()) return;
    ghostRuns.push_back({range.begin(), ghostCandidates.size(), found.size()});
    ghostCandidates.insert(ghostCandidates.end(), found.begin(), found.end());
  };
  const tbb::blocked_range<std::size_t> bins(0, binCount);
  const std::size_t work = static_cast<std::size_t>(chunkHigh - chunkLow + 1) * classCount;  // at most
  if (work < parallel_.work) writeBins(bins);
  else tbb::parallel_for(bins, writeBins);

  double lost = lostVoxels(changedClass, lostOf, airVoxelsLost, &columns_[classLow]);
  if (std::any_of(changedClass.begin(), changedClass.end(), [](char changed) { return changed != 0; })) {
    changedClassLow_ = changedClassHigh_ < changedClassLow_ ? classLow : std::min(changedClassLow_, classLow);
    changedClassHigh_ = std::max(changedClassHigh_, classHigh);
    changedChunkLow_ = changedChunkHigh_ < changedChunkLow_ ? chunkLow : std::min(changedChunkLow_, chunkLow);
    changedChunkHigh_ = std::max(changedChunkHigh_, chunkHigh);
  }

  // Ghosts (region_writer.cpp, step 4), only after a write that removed material. All are
  // found before any is cleared; clearing cannot change another's verdict (a ghost is no
  // material before or after).
  if (!adding && lost != 0.0) {
    const float material = w.notMaterial;
    struct Ghost {
      int c, cell;
    };
    // Each candidate's verdict for each of its class's orbits, in parallel (reads only).
    struct Candidate {
      Ghost at;
      std::size_t firstVerdict;  // in ghostOrbit: one per orbit of its class
    };
    std::vector<Candidate> candidates;
    std::size_t verdicts = 0;
    const auto byFirstBin = [](const Run& a, const Run& b) { return a.firstBin < b.firstBin; };
    if (!std::is_sorted(ghostRuns.begin(), ghostRuns.end(), byFirstBin)) {  // written on one thread, they are
      std::sort(ghostRuns.begin(), ghostRuns.end(), byFirstBin);
      std::vector<Candidates> inOrder;
      inOrder.reserve(ghostCandidates.size());
      for (const Run& run : ghostRuns)
        inOrder.insert(inOrder.end(), ghostCandidates.begin() + run.start, ghostCandidates.begin() + run.start + run.size);
      ghostCandidates = std::move(inOrder);
    }
    for (const Candidates& found : ghostCandidates) {
      const int c = classLow + found.n;
      for (int bit = 0; bit < kChunk; ++bit)
        if ((found.bits >> bit) & 1) {
          candidates.push_back({{c, found.chunk * kChunk + bit}, verdicts});
          verdicts += orbitStart_[c + 1] - orbitStart_[c];
        }
    }
    std::vector<std::uint8_t> ghostOrbit(verdicts);
    const auto decide = [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t m = range.begin(); m != range.end(); ++m) {
        const auto& [at, first] = candidates[m];
        if (materialAboveOrBelow(at.c, at.cell, material)) continue;  // no orbit is a ghost: its verdicts stay 0
        for (int o = orbitStart_[at.c]; o < orbitStart_[at.c + 1]; ++o)
          ghostOrbit[first + (o - orbitStart_[at.c])] = isGhost(orbits_[o].first, orbits_[o].second, kBase_ + at.cell, material);
      }
    };
    const tbb::blocked_range<std::size_t> all(0, candidates.size(), 64);
    if (verdicts < parallel_.verdicts) decide(all);
    else tbb::parallel_for(all, decide);
    std::vector<Ghost> ghosts;                            // the whole class's cell
    std::vector<std::pair<Ghost, VoxelIndex>> airVoxels;  // some of its columns only
    for (const auto& [at, first] : candidates) {
      const int orbitCount = orbitStart_[at.c + 1] - orbitStart_[at.c];
      const int ghostOrbits = static_cast<int>(std::count(ghostOrbit.begin() + first, ghostOrbit.begin() + first + orbitCount, 1));
      if (ghostOrbits == 0) continue;
      if (ghostOrbits == orbitCount) {
        ghosts.push_back(at);
        continue;
      }
      // The class's columns disagree: the voxels of the ghosts' orbits become air voxels.
      for (int o = 0; o < orbitCount; ++o) {
        if (!ghostOrbit[first + o]) continue;
        const auto [i, j] = orbits_[orbitStart_[at.c] + o];
        for (const auto& [x, y] : {std::pair{i, j}, {j, i}})
          for (const int sx : {1, -1})
            for (const int sy : {1, -1}) airVoxels.push_back({at, {sx * x, sy * y, kBase_ + at.cell}});
      }
    }
    const auto valueOf = [this](const Ghost& ghost) {
      std::uint8_t bits;
      return cellsOf(ghost.c, ghost.cell / kChunk, bits)[ghost.cell % kChunk];
    };
    for (const auto& [ghost, voxel] : airVoxels) {
      if (airVoxels_.count(keyOf(voxel.i, voxel.j, voxel.k))) continue;  // an orbit's image seen twice
      if (voxel.j == 0 && voxel.i >= 0 && valueOf(ghost) < 0.0f) meridianFlips_.add(voxel.i, voxel.k);
      lost += std::clamp(0.5 - valueOf(ghost) / h_, 0.0, 1.0);
      addAirVoxel(voxel, ghost.c, ghost.cell);
      markChanged(ghost.c, ghost.cell / kChunk);
    }
    for (const Ghost& ghost : ghosts) {
      const int chunk = ghost.cell / kChunk, bit = ghost.cell % kChunk;
      ChunkCells cells;
      open(ghost.c, chunk, cells);
      float& value = cells.values[bit];
      if (const int i = meridianColumn_[ghost.c]; value < 0.0f && i >= 0 && !isAirVoxel(ghost.c, i, 0, kBase_ + ghost.cell))
        meridianFlips_.add(i, kBase_ + ghost.cell);
      lost += std::clamp(0.5 - value / h_, 0.0, 1.0) * (columns_[ghost.c] - airVoxelsIn(ghost.c, ghost.cell));
      dropAirVoxels(ghost.c, ghost.cell);
      value = band_;
      *cells.activeBits &= static_cast<std::uint8_t>(~(1u << bit));
      markChanged(ghost.c, chunk);
      store(ghost.c, chunk, cells);
    }
  }
  return lost;
}

std::vector<VoxelIndex> RevolvedTable::changedLeaves() {
  std::vector<VoxelIndex> leaves;
  if (changedClassHigh_ < changedClassLow_) return leaves;
  const std::int64_t nLow = sumOfSquares_[changedClassLow_], nHigh = sumOfSquares_[changedClassHigh_];
  const int extent = std::min(halfWidth_, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(nHigh)))));
  // The nearest and farthest i² (or j²) over the eight indices a leaf spans along one axis.
  const auto nearest = [](int a) { return a > 0 ? std::int64_t{a} * a : a + kChunk - 1 < 0 ? std::int64_t{a + kChunk - 1} * (a + kChunk - 1) : 0; };
  const auto farthest = [](int a) { return std::max(std::int64_t{a} * a, std::int64_t{a + kChunk - 1} * (a + kChunk - 1)); };
  std::vector<int> classes;
  for (int x = alignDown(-extent); x <= extent; x += kChunk)
    for (int y = alignDown(-extent); y <= extent; y += kChunk) {
      if (nearest(x) + nearest(y) > nHigh || farthest(x) + farthest(y) < nLow) continue;
      classes.clear();
      for (int i = x; i < x + kChunk; ++i)
        for (int j = y; j < y + kChunk; ++j) {
          const int c = classOf(i, j);
          if (c >= changedClassLow_ && c <= changedClassHigh_) classes.push_back(c);
        }
      std::sort(classes.begin(), classes.end());
      classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
      for (int chunk = changedChunkLow_; chunk <= changedChunkHigh_; ++chunk)
        if (std::any_of(classes.begin(), classes.end(), [&](int c) { return isChanged(c, chunk); }))
          leaves.push_back({x, y, kBase_ + chunk * kChunk});
    }
  forgetChanges();
  return leaves;
}

void RevolvedTable::forgetChanges() {
  for (int c = changedClassLow_; c <= changedClassHigh_; ++c)
    for (int word = changedChunkLow_ / 64; word <= changedChunkHigh_ / 64; ++word)
      changed_[static_cast<std::size_t>(c) * changedWords_ + word] = 0;
  changedClassLow_ = 0;
  changedClassHigh_ = -1;
  changedChunkLow_ = 0;
  changedChunkHigh_ = -1;
}

}  // namespace lathesim::sim
