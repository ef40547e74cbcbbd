#pragma once
// The setup file's [[offset]] tables: the tool offsets T words select (interp/compensation/tool_offset.hpp).
//   [[offset]]
//   number = 1        # 1..99, required; T0101 selects it
//   x = 0.0           # geometry shift in X, a diameter (mm)
//   z = 0.0           # geometry shift in Z (mm)
//   radius = 0.8      # nose radius R (mm, ≥ 0) used by G41/G42
//   tip = 3           # imaginary tip number 0–9 used by G41/G42
//   wear_x = 0.0      # wear shift in X, a diameter (mm)
//   wear_z = 0.0      # wear shift in Z (mm)
// All but number are optional and 0 when left out.
// And the [[work_offset]] tables: the work coordinate systems G54–G59 select.
//   [[work_offset]]
//   code = "G55"      # G54…G59, required
//   x = 0.0           # where that system's X0 lies in the setup's frame, a diameter (mm)
//   z = -40.0         # where its Z0 lies (mm)
// A system no table names has zero shift (G54, the power-on system, usually has).

#include <functional>
#include <string>

#include <toml++/toml.h>

#include "interp/compensation/tool_offset.hpp"
#include "interp/state/work_frame.hpp"

namespace lathesim::setup {

/// Reports one problem at a place in the file.
using ReportProblem = std::function<void(const toml::source_region& where, std::string message)>;

/// Reads the `offset` key's value (an array of tables) into `offsets`; every problem (a
/// wrong type, an unknown key, a number defined twice, a negative radius, a tip outside
/// 0–9) is reported naming the key, and the offsets read without problems are kept.
void readOffsets(const toml::node& node, interp::ToolOffsets& offsets, const ReportProblem& report);

/// Reads the `work_offset` key's value (an array of tables) into `offsets` (index 1…6 for
/// G54…G59, radius and Z), reporting problems as readOffsets does.
void readWorkOffsets(const toml::node& node, interp::WorkOffsets& offsets, const ReportProblem& report);

}  // namespace lathesim::setup
