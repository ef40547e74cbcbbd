// [macro] → MacroSetup; see macro_setup.hpp for the keys.

#include "setup/macro_setup.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "interp/macro/variables.hpp"

namespace lathesim::setup {
namespace {

void readVariables(const toml::node& node, std::map<int, double>& variables, const ReportProblem& report) {
  const auto* table = node.as_table();
  if (table == nullptr) {
    report(node.source(), "macro.variables must be a table of variable numbers and values, e.g. { 500 = 20.0 }");
    return;
  }
  for (const auto& [key, value] : *table) {
    const std::string_view text = key.str();
    int number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    const std::string name = "macro.variables." + std::string(text);
    if (error != std::errc() || end != text.data() + text.size() || !interp::macro::VariableStore::isCommon(number)) {
      report(key.source(), name + ": the key must be the number of a common variable, 100–199 or 500–999");
      continue;
    }
    std::optional<double> parsed;
    if (const auto* i = value.as_integer()) parsed = static_cast<double>(i->get());
    if (const auto* f = value.as_floating_point()) parsed = f->get();
    if (!parsed || !std::isfinite(*parsed)) {
      report(value.source(), name + " must be a number");
      continue;
    }
    variables[number] = *parsed;
  }
}

}  // namespace

void readMacroSetup(const toml::node& node, MacroSetup& macro, const ReportProblem& report) {
  const auto* table = node.as_table();
  if (table == nullptr) {
    report(node.source(), "macro must be a table ([macro])");
    return;
  }
  for (const auto& [key, value] : *table) {
    if (key.str() == "max_steps") {
      const auto* integer = value.as_integer();
      if (integer == nullptr || integer->get() < 1) {
        report(value.source(), "macro.max_steps must be a whole number ≥ 1 (blocks run again)");
        continue;
      }
      macro.maxSteps = integer->get();
    } else if (key.str() == "variables") {
      readVariables(value, macro.variables, report);
    } else {
      report(key.source(), "unknown key 'macro." + std::string(key.str()) + "' (expected max_steps or variables)");
    }
  }
}

}  // namespace lathesim::setup
