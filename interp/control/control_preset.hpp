#pragma once
// The control as a setting: presets of named parameters (lathe-cycles.md §10), as a real
// control has parameters. Two tables, both in control_preset.cpp:
//   the parameters: each one's key (as the setup's [control] writes it), what it decides,
//                   the values it takes, and where it lives in ControlParameters;
//   the presets:    per control, every parameter's value with the manual's parameter it
//                   stands for and whether that was checked against the manual.
// A preset may be based on another and give only what differs. Adding a preset, a parameter
// or a list-valued parameter is one entry in these tables.

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "interp/control/control_parameters.hpp"

namespace lathesim::interp {

/// A parameter's value as the setup writes it: a name ("linear", "G99"), a number, or a
/// list of names.
using ParameterValue = std::variant<std::string, double, std::vector<std::string>>;

/// The value as a setup would write it: "linear", 0.001, ["2+2"].
std::string parameterValueText(const ParameterValue& value);

/// One parameter in force, as report.json lists it.
struct ControlSetting {
  std::string key;
  ParameterValue value;
  std::string manual;     // the control's own parameter or manual section
  bool verified = false;  // checked against the manual (else ⚠ in lathe-cycles.md)
  std::string source;     // "preset", or where it was overridden ("setup", "command line")
};

/// A control: its preset, the parameters in force, and each one's provenance.
struct Control {
  std::string preset;
  ControlParameters parameters;
  std::vector<ControlSetting> settings;  // every parameter, in the table's order

  /// Overrides one parameter. The problem (unknown key, value of the wrong kind or outside
  /// the parameter's values), or nullopt once set. `source` says who set it.
  std::optional<std::string> set(std::string_view key, const ParameterValue& value, std::string_view source);
  /// Whether `key` names a parameter.
  bool knows(std::string_view key) const;
};

inline constexpr std::string_view kDefaultControlPreset = "gsk980tdi";

/// The preset named `name`, or nullopt.
std::optional<Control> controlPreset(std::string_view name);

/// The presets' names: gsk980tdi, fanuc-0i-t, haas.
std::vector<std::string_view> controlPresets();

/// Every parameter's key, in the table's order.
std::vector<std::string_view> controlParameterKeys();

}  // namespace lathesim::interp
