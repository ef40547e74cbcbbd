// Writing a revolved region into the table (RevolvedTable::write): the classes and chunks it
// can reach, written a bin of classes at a time (in parallel when the write is big), then the
// ghosts it left cleared. The same values, bits and lost material as the level set's writer
// (region_writer.cpp), to the last bit.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <utility>

#include "sim/column_write.hpp"
#include "sim/revolved_table.hpp"

namespace lathesim::sim {
namespace {

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

// A bin of this many classes or more reads the region through a plan of its place (see
// RevolvedRegion::planColumn): one edge a piece and cell rather than all of them.
constexpr int kPlannedClasses = 4;
// The change bound is asked about a group of this many chunks at a time (reachedChunks).
constexpr int kGroup = 8;

}  // namespace

// A chunk's ghost candidates (class n of the write's first, its chunk, a bit per cell),
// gathered by each task and then put in class and chunk order, the order in which a single
// thread would have found them. A task writes a range of bins in order, so its own candidates
// are in that order already: only the tasks' runs need ordering, by their first bins.
struct RevolvedTable::Candidates {
  int n, chunk;
  std::uint8_t bits;
};

// A chunk of a bin of classes as a write finds it (RevolvedTable::write).
struct RevolvedTable::Place {
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
struct RevolvedTable::WriteScratch {
  std::vector<RevolvedRegion> nearby;
  std::vector<RevolvedRegion::ColumnPlan> plans;
  std::vector<Place> places;
  std::vector<Candidates> found;
  std::vector<int> reached;  // chunks of the bin being written
};
RevolvedTable::WriteScratch& RevolvedTable::threadScratch() {
  thread_local WriteScratch scratch;
  return scratch;
}

struct RevolvedTable::Ghost {
  int c, cell;
};

// A write while it runs: what it writes, the box of classes and chunks it can reach, its bins,
// and what its tasks found (lost material per class, ghost candidates, which classes changed).
struct RevolvedTable::WritePass {
  struct Run {
    std::size_t firstBin, start, size;  // a task's candidates: ghostCandidates[start, start + size)
  };
  const RevolvedRegion& region;
  bool adding;
  const RevolvedRegion* changes;
  ColumnWrite w;
  double changeMargin;
  int classLow, classHigh, chunkLow, chunkHigh;
  std::vector<double> lostOf;
  // Air voxels lost nothing when their class's cell did: per class, voxels to take back.
  std::vector<double> airVoxelsLost;
  std::vector<Candidates> ghostCandidates;
  std::vector<Run> ghostRuns;
  std::mutex ghostCandidatesMutex;
  std::vector<char> changedClass;
  std::vector<int> binStart;  // the first class of each bin, then one past the last
  double placeRadius, changeReach, farReach;
};

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
  WritePass pass{region, adding, changes, w, changeMargin, classLow, classHigh, chunkLow, chunkHigh,
                 std::vector<double>(classCount, 0.0), std::vector<double>(classCount, 0.0), {}, {}, {},
                 std::vector<char>(classCount, 0), {}, 0.0, 0.0, 0.0};
  // Classes come in bins one voxel wide in ρ (at 22 mm about a hundred classes a bin): what
  // depends on the place only — whether the change bound reaches it, the region near it
  // (RevolvedRegion::nearInto, as the writer takes it per leaf: only the pieces and edges that
  // can be nearest there), whether the region is far or covers it — is asked once per bin and
  // chunk, for a place half a voxel wider. Then the bin's classes are written one after
  // another, each along its chunks: a class's slots and cells lie together in memory.
  pass.binStart.push_back(classLow);
  for (int bin = binOfClass_[classLow] + 1; bin <= binOfClass_[classHigh]; ++bin) pass.binStart.push_back(binFirst_[bin]);
  pass.binStart.push_back(classHigh + 1);
  const double binHalfWidth = 0.5 * h_;
  pass.placeRadius = 0.5 * kChunk * h_ + binHalfWidth + reach;
  pass.changeReach = binHalfWidth + changeMargin;
  const double cellReach = std::hypot(0.5 * (kChunk - 1) * h_, binHalfWidth);
  pass.farReach = cellReach + band_ + h_;

  const auto writeBins = [&](const tbb::blocked_range<std::size_t>& range) { writeBinRange(pass, range.begin(), range.end()); };
  const tbb::blocked_range<std::size_t> bins(0, pass.binStart.size() - 1);
  const std::size_t work = static_cast<std::size_t>(chunkHigh - chunkLow + 1) * classCount;  // at most
  if (work < parallel_.work) writeBins(bins);
  else tbb::parallel_for(bins, writeBins);

  double lost = lostVoxels(pass.changedClass, pass.lostOf, pass.airVoxelsLost, &columns_[classLow]);
  if (std::any_of(pass.changedClass.begin(), pass.changedClass.end(), [](char changed) { return changed != 0; })) {
    changedClassLow_ = changedClassHigh_ < changedClassLow_ ? classLow : std::min(changedClassLow_, classLow);
    changedClassHigh_ = std::max(changedClassHigh_, classHigh);
    changedChunkLow_ = changedChunkHigh_ < changedChunkLow_ ? chunkLow : std::min(changedChunkLow_, chunkLow);
    changedChunkHigh_ = std::max(changedChunkHigh_, chunkHigh);
  }
  if (!adding && lost != 0.0) clearGhosts(pass, lost);
  return lost;
}

void RevolvedTable::reachedChunks(const WritePass& pass, double rhoMid, std::vector<int>& reached) const {
  // The chunks of a bin that the change bound reaches (every chunk of the box without one):
  // a group of chunks at a time, then at each chunk's own cells rather than its centre (a
  // chunk is 8 voxels tall, and a move's sliver of change is often thinner than that). A
  // tool's flanks leave slivers along their whole length, so the box is often wide and the
  // bound reaches a few of its places. Asked by the task that writes the bin.
  reached.clear();
  for (int group = pass.chunkLow; group <= pass.chunkHigh; group += kGroup) {
    const int groupEnd = std::min(pass.chunkHigh + 1, group + kGroup);
    if (pass.changes) {
      const double halfHeight = 0.5 * ((groupEnd - group) * kChunk - 1) * h_;
      const double zMid = (kBase_ + group * kChunk) * h_ + halfHeight;
      if (pass.changes->signedDistance(rhoMid, zMid, halfHeight + pass.changeReach + h_) > halfHeight + pass.changeReach)
        continue;
    }
    for (int chunk = group; chunk < groupEnd; ++chunk) {
      if (pass.changes) {
        double toChanges[kChunk];
        pass.changes->signedDistanceColumn(rhoMid, (kBase_ + chunk * kChunk) * h_, h_, pass.changeReach + h_, toChanges);
        if (*std::min_element(toChanges, toChanges + kChunk) > pass.changeReach) continue;
      }
      reached.push_back(chunk);
    }
  }
}

void RevolvedTable::writeBinRange(WritePass& pass, std::size_t binBegin, std::size_t binEnd) {
  WriteScratch& mine = threadScratch();
  const std::size_t boxChunks = pass.chunkHigh - pass.chunkLow + 1;
  if (mine.nearby.size() < boxChunks) mine.nearby.resize(boxChunks);
  if (mine.plans.size() < boxChunks) mine.plans.resize(boxChunks);
  std::vector<Place>& places = mine.places;
  std::vector<Candidates>& found = mine.found;
  found.clear();
  MeridianBox flips;  // removals only: an addition turns no material to air
  for (std::size_t bin = binBegin; bin != binEnd; ++bin) {
    const int first = pass.binStart[bin], last = pass.binStart[bin + 1];
    const double rhoMid = (std::floor(rho_[first] / h_) + 0.5) * h_;
    places.clear();
    reachedChunks(pass, rhoMid, mine.reached);
    for (const int chunk : mine.reached) {
      const int k0 = kBase_ + chunk * kChunk;
      RevolvedRegion* const local = &mine.nearby[chunk - pass.chunkLow];
      pass.region.nearInto(rhoMid, (k0 + 0.5 * kChunk) * h_, pass.placeRadius, *local);
      if (local->empty()) continue;
      // The region's distance changes by at most the distance moved (each piece's is
      // 1-Lipschitz, inside and out, and so is their minimum): from the place's centre to
      // its cells, at most cellReach. Beyond reach nothing changes and nothing is a ghost
      // candidate; deep inside, every open cell is filled, as writeColumn would fill it.
      const double centre = local->signedDistance(rhoMid, (k0 + 0.5 * (kChunk - 1)) * h_, pass.farReach + h_);
      if (centre > pass.farReach) continue;
      const bool covered = centre < -pass.farReach;
      RevolvedRegion::ColumnPlan* plan = nullptr;
      if (!covered && last - first >= kPlannedClasses) {
        plan = &mine.plans[chunk - pass.chunkLow];
        local->planColumn(rho_[first], rho_[last - 1], k0 * h_, h_, *plan);
      }
      places.push_back({chunk, covered, local, plan});
    }
    for (int c = first; c < last; ++c) {
      if (!places.empty() && c + 1 < last) {
        // The next classes' table lies elsewhere in memory: ask for it while this one is
        // written (their slots two ahead, the cells of the next one's first chunk).
        const int chunk = places.front().chunk;
        if (c + 2 < last) __builtin_prefetch(&slots_[static_cast<std::size_t>(c + 2) * chunks_ + chunk]);
        const std::uint16_t slot = slots_[static_cast<std::size_t>(c + 1) * chunks_ + chunk];
        if (slot < kSolidChunk) __builtin_prefetch(&classes_[c + 1].pool[slot]);
      }
      for (const Place& place : places) writeChunk(pass, c, place, found, flips);
    }
  }
  if (found.empty() && flips.empty()) return;
  const std::lock_guard<std::mutex> lock(pass.ghostCandidatesMutex);
  meridianFlips_.add(flips);
  if (found.empty()) return;
  pass.ghostRuns.push_back({binBegin, pass.ghostCandidates.size(), found.size()});
  pass.ghostCandidates.insert(pass.ghostCandidates.end(), found.begin(), found.end());
}

void RevolvedTable::writeChunk(WritePass& pass, int c, const Place& place, std::vector<Candidates>& found,
                               MeridianBox& flips) {
  const auto& [chunk, covered, local, plan] = place;
  const bool adding = pass.adding;
  const ColumnWrite& w = pass.w;
  const int n = c - pass.classLow;
  const bool onMeridian = !adding && meridianColumn_[c] >= 0;  // its turning to air is noted
  const int k0 = kBase_ + chunk * kChunk;
  std::uint16_t& slot = slots_[static_cast<std::size_t>(c) * chunks_ + chunk];
  // Uniform and already as deep in the region's state as the band allows (air for a
  // removal, solid for an addition): no cell is open, nothing to read or write.
  if (slot == (adding ? kSolidChunk : kAirChunk)) return;
  if (covered) {  // a uniform chunk turns over whole: what fill() would do, without its cells
    if (slot == (adding ? kAirChunk : kSolidChunk)) {  // no air voxels: they are in mixed chunks
      if (onMeridian) noteFlips(c, chunk, solidCells_, airCells_, flips);
      slot = adding ? kSolidChunk : kAirChunk;
      pass.lostOf[n] += adding ? -kChunk : kChunk;
      markChanged(c, chunk);
      pass.changedClass[n] = 1;
      return;
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
        pass.airVoxelsLost[n] += air * (std::clamp(0.5 - before[k] * w.inverseVoxel, 0.0, 1.0) -
                                        std::clamp(0.5 - values[k] * w.inverseVoxel, 0.0, 1.0));
  };
  if (covered) {
    bool changed = false;
    pass.lostOf[n] += fill(values, *cells.activeBits, w, changed);
    if (changed) {
      if (onMeridian) noteFlips(c, chunk, before, values, flips);
      takeBackAirVoxels();
      markChanged(c, chunk);
      pass.changedClass[n] = 1;
      store(c, chunk, cells);
    }
    return;
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
  pass.lostOf[n] += writeColumn(w, values, psi, active, ghostBits);
  if (std::memcmp(before, values, sizeof before) != 0 || active != activeBefore) {
    if (onMeridian) noteFlips(c, chunk, before, values, flips);
    takeBackAirVoxels();
    markChanged(c, chunk);
    pass.changedClass[n] = 1;
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

// Ghosts (region_writer.cpp, step 4), only after a write that removed material. All are found
// before any is cleared; clearing cannot change another's verdict (a ghost is no material
// before or after).
void RevolvedTable::clearGhosts(WritePass& pass, double& lost) {
  std::vector<Ghost> ghosts;                            // the whole class's cell
  std::vector<std::pair<Ghost, VoxelIndex>> airVoxels;  // some of its columns only
  findGhosts(pass, ghosts, airVoxels);
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

void RevolvedTable::findGhosts(WritePass& pass, std::vector<Ghost>& ghosts,
                               std::vector<std::pair<Ghost, VoxelIndex>>& airVoxels) const {
  const float material = pass.w.notMaterial;
  // Each candidate's verdict for each of its class's orbits, in parallel (reads only).
  struct Candidate {
    Ghost at;
    std::size_t firstVerdict;  // in ghostOrbit: one per orbit of its class
  };
  std::vector<Candidate> candidates;
  std::size_t verdicts = 0;
  using Run = WritePass::Run;
  std::vector<Run>& ghostRuns = pass.ghostRuns;
  std::vector<Candidates>& ghostCandidates = pass.ghostCandidates;
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
    const int c = pass.classLow + found.n;
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

}  // namespace lathesim::sim
