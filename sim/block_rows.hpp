#pragma once
// The simulation's rows, one for each block that made moves (BlockRemoval), wherever they are
// kept: in its result (SimulationResult::blocks), or spooled to a temporary file as each block
// is finished (Simulation::sendBlocksTo), so that a long program's run holds nothing a block.

#include <functional>
#include <type_traits>
#include <vector>

#include "interp/output/spool_file.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {

class BlockRows {
 public:
  virtual ~BlockRows() = default;
  /// Each row, in program order.
  virtual void forEach(const std::function<void(const BlockRemoval&)>& visit) const = 0;
};

/// Rows held in memory: a SimulationResult's.
class HeldBlockRows final : public BlockRows {
 public:
  explicit HeldBlockRows(const std::vector<BlockRemoval>& rows) : rows_(rows) {}
  void forEach(const std::function<void(const BlockRemoval&)>& visit) const override {
    for (const BlockRemoval& row : rows_) visit(row);
  }

 private:
  const std::vector<BlockRemoval>& rows_;
};

/// Rows spooled as they come, read back a few thousand at a time.
class SpooledBlockRows final : public BlockRows {
 public:
  void add(const BlockRemoval& row) { file_.append(&row, sizeof row); }
  void forEach(const std::function<void(const BlockRemoval&)>& visit) const override;

 private:
  static_assert(std::is_trivially_copyable_v<BlockRemoval>, "rows are spooled as their bytes");
  interp::SpoolFile file_{"the blocks' rows"};
};

/// Which numbers (blocks, lines) a pass over the rows meets more than once, two bits a number:
/// for the readers that sum apart the rows of what runs several times (a subprogram, a loop)
/// and take the others one by one as they come, instead of holding a sum for every number.
class MetTwice {
 public:
  void note(int number) {
    const auto n = static_cast<std::size_t>(number);
    if (n >= once_.size()) once_.resize(n + 1), twice_.resize(n + 1);
    if (once_[n]) twice_[n] = true;
    once_[n] = true;
  }
  bool has(int number) const {
    const auto n = static_cast<std::size_t>(number);
    return n < twice_.size() && twice_[n];
  }

 private:
  std::vector<bool> once_, twice_;
};

}  // namespace lathesim::sim
