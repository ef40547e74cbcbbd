// [[offset]] tables → interp::ToolOffsets; see offset_setup.hpp for the keys.

#include "setup/offset_setup.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <string_view>

namespace lathesim::setup {
namespace {

constexpr std::string_view kKeys[] = {"number", "x", "z", "radius", "tip", "wear_x", "wear_z"};

std::string knownKeys() {
  std::string text;
  for (std::string_view key : kKeys) text += std::string(text.empty() ? "" : ", ") + std::string(key);
  return text;
}

/// A number in mm (a TOML integer or float), or nullopt with the problem reported.
std::optional<double> lengthAt(const toml::table& table, std::string_view key,
                               const std::string& name, const ReportProblem& report) {
  const toml::node* node = table.get(key);
  if (node == nullptr) return 0.0;
  std::optional<double> value;
  if (const auto* i = node->as_integer()) value = static_cast<double>(i->get());
  if (const auto* f = node->as_floating_point()) value = f->get();
  if (!value || !std::isfinite(*value)) {
    report(node->source(), name + "." + std::string(key) + " must be a number of mm");
    return std::nullopt;
  }
  return value;
}

/// An integer in [low, high], or nullopt with the problem reported.
std::optional<int> integerAt(const toml::node& node, const std::string& key, int low, int high,
                             const ReportProblem& report) {
  const auto* integer = node.as_integer();
  if (integer == nullptr || integer->get() < low || integer->get() > high) {
    report(node.source(), key + " must be an integer " + std::to_string(low) + ".." +
                              std::to_string(high));
    return std::nullopt;
  }
  return static_cast<int>(integer->get());
}

std::optional<std::pair<int, interp::ToolOffset>> readOffset(const toml::table& table,
                                                             const std::string& name,
                                                             const ReportProblem& report) {
  bool ok = true;
  for (auto&& [key, node] : table) {
    bool known = false;
    for (std::string_view k : kKeys) known = known || key.str() == k;
    if (!known) {
      report(key.source(), "unknown key '" + name + "." + std::string(key.str()) +
                               "' (expected " + knownKeys() + ")");
      ok = false;
    }
  }
  std::optional<int> number;
  if (const auto* node = table.get("number")) {
    number = integerAt(*node, name + ".number", 1, 99, report);
  } else {
    report(table.source(), name + " has no number (add number = 1..99)");
  }
  interp::ToolOffset offset;
  const auto x = lengthAt(table, "x", name, report);
  const auto z = lengthAt(table, "z", name, report);
  const auto radius = lengthAt(table, "radius", name, report);
  const auto wearX = lengthAt(table, "wear_x", name, report);
  const auto wearZ = lengthAt(table, "wear_z", name, report);
  if (radius && *radius < 0) {
    report(table.get("radius")->source(), name + ".radius is a nose radius and must be ≥ 0");
    ok = false;
  }
  std::optional<int> tip = 0;
  if (const auto* node = table.get("tip")) tip = integerAt(*node, name + ".tip", 0, 9, report);
  if (!ok || !number || !x || !z || !radius || !wearX || !wearZ || !tip) return std::nullopt;
  offset.xDiameterMm = *x;
  offset.zMm = *z;
  offset.radiusMm = *radius;
  offset.tip = *tip;
  offset.wearXDiameterMm = *wearX;
  offset.wearZMm = *wearZ;
  return std::pair{*number, offset};
}

constexpr std::string_view kWorkKeys[] = {"code", "x", "z"};
constexpr std::string_view kWorkCodes[] = {"G54", "G55", "G56", "G57", "G58", "G59"};

/// The system a [[work_offset]] names: 1…6 for G54…G59.
std::optional<int> workSystemAt(const toml::table& table, const std::string& name, const ReportProblem& report) {
  const toml::node* node = table.get("code");
  if (node == nullptr) {
    report(table.source(), name + " has no code (add code = \"G54\" … \"G59\")");
    return std::nullopt;
  }
  if (const auto* text = node->as_string()) {
    for (std::size_t i = 0; i < std::size(kWorkCodes); ++i)
      if (text->get() == kWorkCodes[i]) return static_cast<int>(i) + 1;
  }
  report(node->source(), name + ".code must be one of \"G54\" … \"G59\"");
  return std::nullopt;
}

}  // namespace

void readWorkOffsets(const toml::node& node, interp::WorkOffsets& offsets, const ReportProblem& report) {
  const auto* array = node.as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    report(node.source(), "work_offset must be given as [[work_offset]] tables");
    return;
  }
  std::map<int, std::size_t> seen;  // system → 1-based index of its first table
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto& table = *array->get(i)->as_table();
    const std::string name = "work_offset[" + std::to_string(i + 1) + "]";
    bool ok = true;
    for (auto&& [key, value] : table) {
      if (std::find(std::begin(kWorkKeys), std::end(kWorkKeys), key.str()) != std::end(kWorkKeys)) continue;
      report(key.source(), "unknown key '" + name + "." + std::string(key.str()) + "' (expected code, x, z)");
      ok = false;
    }
    const auto system = workSystemAt(table, name, report);
    const auto x = lengthAt(table, "x", name, report);
    const auto z = lengthAt(table, "z", name, report);
    if (!ok || !system || !x || !z) continue;
    const auto [first, inserted] = seen.emplace(*system, i + 1);
    if (!inserted) {
      report(table.get("code")->source(), std::string(kWorkCodes[*system - 1]) + " is given twice (work_offset[" +
                                              std::to_string(first->second) + "] and " + name + ")");
      continue;
    }
    offsets[static_cast<std::size_t>(*system)] = RZ(*x / 2.0, *z);
  }
}

void readOffsets(const toml::node& node, interp::ToolOffsets& offsets, const ReportProblem& report) {
  const auto* array = node.as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    report(node.source(), "offset must be given as [[offset]] tables");
    return;
  }
  std::map<int, std::size_t> seen;  // offset number → 1-based index of its first table
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto& table = *array->get(i)->as_table();
    const std::string name = "offset[" + std::to_string(i + 1) + "]";
    auto read = readOffset(table, name, report);
    if (!read) continue;
    const auto [first, inserted] = seen.emplace(read->first, i + 1);
    if (!inserted) {
      report(table.get("number")->source(),
             "offset number " + std::to_string(read->first) + " is defined twice (offset[" +
                 std::to_string(first->second) + "] and " + name + ")");
      continue;
    }
    offsets[read->first] = read->second;
  }
}

}  // namespace lathesim::setup
