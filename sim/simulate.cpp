#include "sim/simulate.hpp"

#include "sim/simulation.hpp"

namespace lathesim::sim {

bool spindleTurns(const interp::Move& move) { return move.spindleOn && move.spindleS > 0.0; }

void recordCollision(std::vector<Collision>& collisions, const interp::Move& move, const char* kind, double volumeMm3) {
  // The block's collisions are the last ones, of one or more kinds.
  for (auto c = collisions.rbegin(); c != collisions.rend() && c->line == move.line && c->column == move.column; ++c) {
    if (c->kind != kind) continue;
    c->volumeMm3 += volumeMm3;
    return;
  }
  collisions.push_back({move.line, move.column, kind, volumeMm3, move.tool, move.to});
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks) {
  return simulate(toolpath, tools, stock, progress, checks, {});
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks,
                          const ToolThicknesses& thicknesses, const CutObserver& observer) {
  Simulation simulation(toolpath, tools, stock, progress, checks, thicknesses, observer);
  for (const interp::Move& move : toolpath.moves) simulation.take(move);
  return simulation.finish(toolpath);
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress) {
  return simulate(toolpath, tools, stock, progress, nullptr, {});
}

}  // namespace lathesim::sim
