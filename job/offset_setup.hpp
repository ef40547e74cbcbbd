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

#include <functional>
#include <string>

#include <toml++/toml.h>

#include "interp/compensation/tool_offset.hpp"

namespace lathesim::job {

/// Reports one problem at a place in the file.
using ReportProblem = std::function<void(const toml::source_region& where, std::string message)>;

/// Reads the `offset` key's value (an array of tables) into `offsets`; every problem (a
/// wrong type, an unknown key, a number defined twice, a negative radius, a tip outside
/// 0–9) is reported naming the key, and the offsets read without problems are kept.
void readOffsets(const toml::node& node, interp::ToolOffsets& offsets, const ReportProblem& report);

}  // namespace lathesim::job
