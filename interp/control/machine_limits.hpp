#pragma once
// What the machine itself allows, from the setup's [machine] section: rapid rates and the
// spindle's top speed. They set G28's path and every move's time, not its geometry.

namespace lathesim::interp {

struct MachineLimits {
  double rapidXMmPerMin = 6000.0;  // X axis (radial travel, mm of radius per minute)
  double rapidZMmPerMin = 8000.0;  // Z axis
  double maxRpm = 3000.0;          // the spindle's top speed; caps G97 S and G96 alike
};

}  // namespace lathesim::interp
