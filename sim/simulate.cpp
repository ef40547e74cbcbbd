#include "sim/simulate.hpp"

#include <stdexcept>

namespace lathesim::sim {
namespace {

ConvexPolygon sweptRegion(const interp::Move& move, const ToolOutlines& tools) {
  const auto tool = tools.find(move.tool);
  if (tool == tools.end())  // interp checks T words against the setup; this is a broken invariant
    throw std::logic_error("move on line " + std::to_string(move.line) + " uses undefined tool " +
                           std::to_string(move.tool));
  return tool->second.sweptAlong(move.from, move.to);
}

}  // namespace

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks) {
  SimulationResult result;
  const auto& moves = toolpath.moves;
  const double voxelVolume = stock.voxelMm() * stock.voxelMm() * stock.voxelMm();
  const int totalBlocks = toolpath.blockCount;

  for (std::size_t first = 0; first < moves.size();) {
    const interp::Move& head = moves[first];
    if (result.blocks.empty() || result.blocks.back().block != head.block)
      result.blocks.push_back({head.block, head.line, head.column, 0.0});
    BlockRemoval& block = result.blocks.back();

    std::size_t end = first + 1;
    if (head.kind == interp::MoveKind::Feed)
      while (end < moves.size() && moves[end].block == head.block && moves[end].kind == interp::MoveKind::Feed) ++end;

    std::vector<ConvexPolygon> pieces;
    for (std::size_t m = first; m < end; ++m) pieces.push_back(sweptRegion(moves[m], tools));
    const double removed = stock.remove(RevolvedRegion(pieces));
    block.removedMm3 += removed;
    if (head.kind == interp::MoveKind::Rapid && removed > kCollisionVoxels * voxelVolume)
      result.collisions.push_back({head.line, head.column, "rapid_into_stock", removed});
    if (checks) checkMoves(*checks, std::span(moves).subspan(first, end - first), stock, result.collisions);

    first = end;
    if (progress && (first == moves.size() || moves[first].block != head.block)) progress(head.block + 1, totalBlocks);
  }
  return result;
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress) {
  return simulate(toolpath, tools, stock, progress, nullptr);
}

}  // namespace lathesim::sim
