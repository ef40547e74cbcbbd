#pragma once
// The setup file's [control] table: the control preset and single parameters overridden
// (interp/control/control_preset.hpp).
//   [control]
//   name = "fanuc-0i-t"              # a preset; gsk980tdi when left out
//   decimal_point_input = "calculator"  # any parameter, by its key
// The preset is chosen first, whatever the keys' order; each other key overrides one parameter.

#include <string_view>

#include <toml++/toml.h>

#include "interp/control/control_preset.hpp"
#include "setup/offset_setup.hpp"

namespace lathesim::setup {

/// Reads `table` into `control`; every problem (an unknown preset or key, a value of the
/// wrong kind) is reported at its key or value.
void readControl(const toml::table& table, interp::Control& control, const ReportProblem& report);

/// The value as the setup file writes it: a string, a number, a boolean (true "on", false
/// "off") or an array of strings; nullopt for anything else.
std::optional<interp::ParameterValue> parameterValueOf(const toml::node& node);

/// `control`'s overrides (every setting not from the preset) applied to preset `name`; nullopt
/// when there is no such preset.
std::optional<interp::Control> withPreset(const interp::Control& control, std::string_view name);

}  // namespace lathesim::setup
