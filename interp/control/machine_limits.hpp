#pragma once
// What the machine itself allows, from the setup's [machine] section: rapid rates, the
// spindle's top speed and the axes' travel. They set G28's path and every move's time, and
// bound where the tool may go.

#include <optional>

namespace lathesim::interp {

/// The stored stroke limits (GSK No.45/46, Fanuc 1320/1321): where the tool's programmed
/// point may go, in the setup's frame. A move beyond them is an overtravel alarm.
struct TravelLimits {
  double xMinDiameterMm = 0;
  double xMaxDiameterMm = 0;
  double zMinMm = 0;
  double zMaxMm = 0;
  bool xDerived = false;  // not stated by the setup: derived from its reference, start and bar
  bool zDerived = false;
};

struct MachineLimits {
  double rapidXMmPerMin = 6000.0;  // X axis (radial travel, mm of radius per minute)
  double rapidZMmPerMin = 8000.0;  // Z axis
  double maxRpm = 3000.0;          // the spindle's top speed; caps G97 S and G96 alike
  std::optional<TravelLimits> travel;  // none: not checked
};

}  // namespace lathesim::interp
