#pragma once
// What the setup says every move must stay clear of: the holder bodies and the chuck.

#include "job/setup.hpp"
#include "sim/holder_check.hpp"

namespace lathesim::job {

sim::CollisionChecks collisionChecksOf(const Setup& setup);

}  // namespace lathesim::job
