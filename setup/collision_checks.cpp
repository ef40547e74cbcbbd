#include "setup/collision_checks.hpp"

namespace lathesim::setup {

sim::CollisionChecks collisionChecksOf(const Setup& setup) {
  sim::CollisionChecks checks;
  for (const auto& tool : setup.tools) {
    checks.cutters.emplace(tool.number, tool.outline);
    if (tool.holderBody) checks.holders.emplace(tool.number, *tool.holderBody);
  }
  checks.chuck = sim::chuckRegions(setup.chuck, setup.stock);
  if (setup.tailstock) checks.tailstock = tailstockRegions(*setup.tailstock);
  return checks;
}

}  // namespace lathesim::setup
