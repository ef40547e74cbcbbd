#pragma once
// What lathesim assumed about the machine because the setup (and the command line) did not
// say it: the tool's start position, each axis's travel, the bar and its face. Said on the
// summary line and in report.json's "machine": {"assumed": {…}}, so a verdict that rests on
// an assumption shows it.

#include <string>
#include <vector>

#include "setup/setup.hpp"

namespace lathesim::setup {

struct MachineAssumption {
  std::string key;             // report.json's key: "start", "travel_x", "travel_z", "stock", "stock_face_z"
  std::vector<double> values;  // the value assumed, in mm: [X diameter, Z], [min, max], [D, L] or [Z]
  std::string text;            // for people: "start X200 Z200"
};

/// Each assumption `setup` makes, in the order above; none when the setup states everything.
std::vector<MachineAssumption> machineAssumptions(const Setup& setup);

/// "start X200 Z200, X travel X-50 to X200, …", for the summary line; empty when none.
std::string assumptionsText(const std::vector<MachineAssumption>& assumptions);

}  // namespace lathesim::setup
