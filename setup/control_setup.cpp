#include "setup/control_setup.hpp"

#include <string>
#include <vector>

namespace lathesim::setup {

std::optional<interp::ParameterValue> parameterValueOf(const toml::node& node) {
  if (const auto* text = node.as_string()) return interp::ParameterValue(text->get());
  if (const auto* integer = node.as_integer()) return interp::ParameterValue(static_cast<double>(integer->get()));
  if (const auto* real = node.as_floating_point()) return interp::ParameterValue(real->get());
  if (const auto* flag = node.as_boolean()) return interp::ParameterValue(std::string(flag->get() ? "on" : "off"));
  if (const auto* array = node.as_array()) {
    std::vector<std::string> names;
    for (const toml::node& element : *array) {
      const auto* text = element.as_string();
      if (text == nullptr) return std::nullopt;
      names.push_back(text->get());
    }
    return interp::ParameterValue(std::move(names));
  }
  return std::nullopt;
}

void readControl(const toml::table& table, interp::Control& control, const ReportProblem& report) {
  if (const auto* node = table.get("name")) {
    const auto* name = node->as_string();
    std::optional<interp::Control> preset = name ? interp::controlPreset(name->get()) : std::nullopt;
    if (preset) {
      control = std::move(*preset);
    } else {
      std::string names;
      for (std::string_view n : interp::controlPresets()) names += (names.empty() ? "\"" : ", \"") + std::string(n) + "\"";
      report(node->source(), "control.name must be one of " + names + " (a control preset)");
    }
  }
  for (auto&& [key, node] : table) {
    if (key.str() == "name") continue;
    const auto value = parameterValueOf(node);
    if (!value) {
      report(node.source(), "control." + std::string(key.str()) + " must be a string, a number or a list of strings");
      continue;
    }
    if (auto problem = control.set(key.str(), *value, "setup"))
      report(control.knows(key.str()) ? node.source() : key.source(), std::move(*problem));
  }
}

std::optional<interp::Control> withPreset(const interp::Control& control, std::string_view name) {
  std::optional<interp::Control> chosen = interp::controlPreset(name);
  if (!chosen) return std::nullopt;
  for (const interp::ControlSetting& setting : control.settings)
    if (setting.source != "preset") (void)chosen->set(setting.key, setting.value, setting.source);
  return chosen;
}

}  // namespace lathesim::setup
