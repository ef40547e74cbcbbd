#pragma once
// The simulation's rows, one for each block that made moves (BlockRemoval), wherever they are
// kept: in its result (SimulationResult::blocks), or spooled to a temporary file as each block
// is finished (Simulation::sendBlocksTo), so that a long program's run holds nothing a block.

#include <functional>
#include <type_traits>
#include <vector>

#include "interp/spool_file.hpp"
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

}  // namespace lathesim::sim
