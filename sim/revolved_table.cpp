#include "sim/revolved_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace lathesim::sim {
namespace {

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