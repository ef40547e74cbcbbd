#include "sim/cut_rules.hpp"

namespace lathesim::sim {

bool spindleTurns(const interp::Move& move) { return move.spindleOn && move.spindleS > 0.0; }

void recordCollision(std::vector<Collision>& collisions, const interp::Move& move, const char* kind, double volumeMm3) {
  // The block's collisions are the last ones, of one or more kinds.
  for (auto c = collisions.rbegin(); c != collisions.rend() && c->line == move.line && c->column == move.column && c->source == move.source; ++c) {
    if (c->kind != kind) continue;
    c->volumeMm3 += volumeMm3;
    return;
  }
  collisions.push_back({move.line, move.column, kind, volumeMm3, move.tool, move.to, move.source});
}

}  // namespace lathesim::sim
