#pragma once
// What the setup says every move must stay clear of: the holder bodies and the chuck.

#include "setup/setup.hpp"
#include "sim/holder_check.hpp"

namespace lathesim::setup {

sim::CollisionChecks collisionChecksOf(const Setup& setup);

}  // namespace lathesim::setup
