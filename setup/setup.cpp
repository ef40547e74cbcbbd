// The setup file: TOML text → Setup, or diagnostics that point at the offending key.
//
// Every section and key is optional; what the file leaves out keeps defaultSetup()'s value.
// [[tool]] is the exception to "key by key": if the file lists any tools, they replace the
// default tool entirely, and each must give its number. All problems in a file are
// reported together; a file with any error yields no Setup.

#include "setup/setup.hpp"

#include "setup/tool_setup.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include <toml++/toml.h>

#include "setup/control_setup.hpp"
#include "setup/offset_setup.hpp"

namespace lathesim::setup {
namespace {

using interp::Diagnostic;
using interp::Severity;

// The default insert outline, [radial, axial] mm from the programmed point. The programmed
// point is the sharp tip at (0, 0); the insert lies above and to the right of it (r ≥ 0,
// z ≥ 0), as for a turning/facing tool that approaches the work from +X and +Z.
// Both flanks leave the tip at 1 in 10 (≈ 5.7°) rather than along the axes: the lower flank
// (0,0)→(10,1) clears the face just cut when the tool feeds towards the axis (G94 step 2),
// and the left flank (0,0)→(1,10) clears the wall just cut when the tool feeds along −Z or
// retracts along +Z (G94 step 3). With flanks exactly on the axes the body would rub the
// finished surfaces instead of staying off them.
constexpr std::array<std::array<double, 2>, 4> kDefaultOutline{{{0, 0}, {10, 1}, {12, 12}, {1, 10}}};

ConvexPolygon defaultOutline() {
  std::vector<RZ> points;
  for (const auto& [r, z] : kDefaultOutline) points.emplace_back(r, z);
  auto checked = ConvexPolygon::fromOutline(points);
  return *checked.polygon;  // a fixed, known-good outline
}


/// A float as TOML would spell it, in the fewest digits that read back the same (-0.2, 5.0).
std::string floatText(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::array<char, 64> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  std::string text(buffer.data(), ec == std::errc{} ? end : buffer.data());
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

/// A value as TOML spells it.
std::string spelling(const toml::node& node) {
  if (node.is_table()) return "{…}";
  if (const auto* array = node.as_array()) {
    std::string text("[");
    for (std::size_t i = 0; i < array->size(); ++i) text += (i ? ", " : "") + spelling(*array->get(i));
    return text + "]";
  }
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) return floatText(f->get());
  if (const auto* s = node.as_string()) return "\"" + s->get() + "\"";
  if (const auto* b = node.as_boolean()) return std::string(b->get() ? "true" : "false");
  std::ostringstream out;  // dates and times
  node.visit([&out](const auto& value) {
    if constexpr (toml::is_value<decltype(value)>) out << value;
  });
  return out.str();
}

/// How a value reads in a message: its TOML spelling when short, else what kind it is.
std::string describe(const toml::node& node) {
  if (node.is_table()) return "a table";
  std::string text = spelling(node);
  if (text.size() > 40) return node.is_array() ? "an array" : node.is_string() ? "a long string" : "a long value";
  return text;
}

/// Collects diagnostics for one file, each placed at a toml++ source position.
class Reporter {
 public:
  Reporter(std::string_view text, std::string fileName) : text_(text), fileName_(std::move(fileName)) {}

  void at(const toml::source_region& where, std::string message, Severity severity = Severity::Error,
          int columnOffset = 0) {
    Diagnostic d;
    d.severity = severity;
    d.file = fileName_;
    d.line = static_cast<int>(where.begin.line);
    d.column = static_cast<int>(where.begin.column) + columnOffset;
    d.message = std::move(message);
    d.sourceLine = interp::lineOf(text_, d.line);
    diagnostics_.push_back(std::move(d));
  }

  std::vector<Diagnostic> take() { return std::move(diagnostics_); }
  const std::string& fileName() const { return fileName_; }
  bool hasErrors() const {
    for (const auto& d : diagnostics_)
      if (d.severity == Severity::Error) return true;
    return false;
  }

 private:
  std::string_view text_;
  std::string fileName_;
  std::vector<Diagnostic> diagnostics_;
};

/// A TOML integer or float as double (integers are accepted where mm are expected).
std::optional<double> numberOf(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

std::string joinKeys(const std::vector<std::string_view>& keys) {
  std::string text;
  std::size_t i = 0;
  for (std::string_view key : keys) {
    if (i > 0) text += (i + 1 == keys.size()) ? " or " : ", ";
    text += key;
    ++i;
  }
  return text;
}

/// Reports every key of `table` not in `known`, as "unknown key 'prefix.key' (expected …)".
void rejectUnknownKeys(const toml::table& table, std::string_view prefix,
                       const std::vector<std::string_view>& known, Reporter& report) {
  for (auto&& [key, node] : table) {
    bool ok = false;
    for (std::string_view k : known) ok = ok || key.str() == k;
    if (ok) continue;
    const std::string what = node.is_table() ? "unknown table '" : "unknown key '";
    report.at(key.source(), what + std::string(prefix) + std::string(key.str()) + "' (expected " +
                                joinKeys(known) + ")");
  }
}

/// A table-valued key: the table, or a wrong-type diagnostic.
const toml::table* tableAt(const toml::node& node, const std::string& name, Reporter& report) {
  if (const auto* table = node.as_table()) return table;
  report.at(node.source(), name + " must be a table ([" + name + "]), got " + describe(node));
  return nullptr;
}

/// A length in mm that must be > 0.
std::optional<double> positiveMm(const toml::node& node, const std::string& name, Reporter& report) {
  const auto value = numberOf(node);
  if (!value || !(*value > 0.0) || !std::isfinite(*value)) {
    report.at(node.source(), name + " must be a positive number of mm, got " + describe(node));
    return std::nullopt;
  }
  return value;
}

/// A coordinate in mm: any finite number.
std::optional<double> finiteMm(const toml::node& node, const std::string& name, Reporter& report) {
  const auto value = numberOf(node);
  if (!value || !std::isfinite(*value)) {
    report.at(node.source(), name + " must be a number of mm, got " + describe(node));
    return std::nullopt;
  }
  return value;
}

void readStock(const toml::table& table, Setup& setup, Reporter& report) {
  sim::StockSpec& stock = setup.stock;
  rejectUnknownKeys(table, "stock.", {"diameter", "length", "face_z", "bore", "material"}, report);
  if (const auto* node = table.get("material")) {
    if (const auto* text = node->as_string()) setup.stockMaterial = text->get();
    else report.at(node->source(), "stock.material must be text in quotes (e.g. \"C45\"), got " + describe(*node));
  }
  if (const auto* node = table.get("diameter"))
    if (auto v = positiveMm(*node, "stock.diameter", report)) stock.diameterMm = *v;
  if (const auto* node = table.get("length"))
    if (auto v = positiveMm(*node, "stock.length", report)) stock.lengthMm = *v;
  if (const auto* node = table.get("face_z"))
    if (auto v = finiteMm(*node, "stock.face_z", report)) {
      stock.faceZMm = *v;
      setup.stockFaceGiven = true;
    }
  if (const auto* node = table.get("bore")) {
    if (auto v = positiveMm(*node, "stock.bore", report)) {
      if (*v < stock.diameterMm) stock.boreMm = *v;
      else
        report.at(node->source(), "stock.bore (the tube's inside diameter, " + floatText(*v) +
                                      " mm) must be smaller than stock.diameter (" + floatText(stock.diameterMm) + " mm)");
    }
  }
}

/// A position given as [X diameter, Z] in mm, as (radius, Z).
std::optional<RZ> positionOf(const toml::node& node, const std::string& name, Reporter& report) {
  const auto* array = node.as_array();
  std::optional<double> x, z;
  if (array && array->size() == 2) {
    x = numberOf(*array->get(0));
    z = numberOf(*array->get(1));
  }
  if (!x || !z || !std::isfinite(*x) || !std::isfinite(*z)) {
    report.at(node.source(), name + " must be [X diameter, Z] in mm, got " + describe(node));
    return std::nullopt;
  }
  if (*x < 0.0) {
    report.at(node.source(), name + " X is a diameter and must not be negative, got " + describe(node));
    return std::nullopt;
  }
  return RZ(*x / 2.0, *z);
}

/// A rate or speed that must be > 0; `unit` names it in the message ("mm/min", "rpm").
std::optional<double> positiveRate(const toml::node& node, const std::string& name, const std::string& unit,
                                   Reporter& report) {
  const auto value = numberOf(node);
  if (!value || !(*value > 0.0) || !std::isfinite(*value)) {
    report.at(node.source(), name + " must be a positive number of " + unit + ", got " + describe(node));
    return std::nullopt;
  }
  return value;
}

void readRapid(const toml::node& node, interp::MachineLimits& machine, Reporter& report) {
  const auto* array = node.as_array();
  std::optional<double> x, z;
  if (array && array->size() == 2) {
    x = numberOf(*array->get(0));
    z = numberOf(*array->get(1));
  }
  if (!x || !z || !(*x > 0.0) || !(*z > 0.0) || !std::isfinite(*x) || !std::isfinite(*z)) {
    report.at(node.source(), "machine.rapid must be [X, Z] rapid rates, positive numbers of mm/min, got " +
                                 describe(node));
    return;
  }
  machine.rapidXMmPerMin = *x;
  machine.rapidZMmPerMin = *z;
}

// A string key that must be one of `choices`; the index of the one given.
std::optional<std::size_t> choiceOf(const toml::node& node, const std::string& name,
                                    std::initializer_list<std::string_view> choices, Reporter& report) {
  if (const auto* text = node.as_string()) {
    std::size_t index = 0;
    for (std::string_view choice : choices) {
      if (text->get() == choice) return index;
      ++index;
    }
  }
  std::string listed;
  for (std::string_view choice : choices) listed += std::string(listed.empty() ? "" : ", ") + '"' + std::string(choice) + '"';
  report.at(node.source(), name + " must be one of " + listed + ", got " + describe(node));
  return std::nullopt;
}

/// A travel range [min, max] in mm, min < max.
std::optional<std::pair<double, double>> rangeOf(const toml::node& node, const std::string& name, Reporter& report) {
  const auto* array = node.as_array();
  std::optional<double> low, high;
  if (array && array->size() == 2) {
    low = numberOf(*array->get(0));
    high = numberOf(*array->get(1));
  }
  if (!low || !high || !std::isfinite(*low) || !std::isfinite(*high) || !(*low < *high)) {
    report.at(node.source(), name + " must be [min, max] in mm with min < max, got " + describe(node));
    return std::nullopt;
  }
  return std::pair{*low, *high};
}

void readMachine(const toml::table& table, Setup& setup, Reporter& report) {
  rejectUnknownKeys(table, "machine.",
                    {"start", "rapid", "max_rpm", "reference", "travel_x", "travel_z", "dialect", "initial_feed_mode",
                     "thread_runout", "zero", "second_reference", "tailstock"},
                    report);
  if (const auto* node = table.get("tailstock"))
    setup.tailstock = readTailstock(*node, [&report](const toml::source_region& where, std::string message) {
      report.at(where, std::move(message));
    });
  if (const auto* node = table.get("travel_x")) setup.travelXDiameterMm = rangeOf(*node, "machine.travel_x", report);
  if (const auto* node = table.get("travel_z")) setup.travelZMm = rangeOf(*node, "machine.travel_z", report);
  if (const auto* node = table.get("dialect")) {
    using interp::kDialects, interp::dialectName;
    if (auto i = choiceOf(*node, "machine.dialect",
                          {dialectName(kDialects[0]), dialectName(kDialects[1]), dialectName(kDialects[2]),
                           dialectName(kDialects[3])},
                          report)) {
      setup.dialect = kDialects[*i];
      setup.dialectBy = "the setup's [machine] dialect";
    }
  }
  // The older spelling of control.power_on_feed_mode.
  if (const auto* node = table.get("initial_feed_mode")) {
    const auto given = std::find_if(setup.control.settings.begin(), setup.control.settings.end(),
                                    [](const interp::ControlSetting& s) { return s.key == "power_on_feed_mode"; });
    if (given != setup.control.settings.end() && given->source != "preset")
      report.at(node->source(), "machine.initial_feed_mode and control.power_on_feed_mode both set the feed mode at "
                                "power-on; give control.power_on_feed_mode alone");
    else if (auto i = choiceOf(*node, "machine.initial_feed_mode", {"per_revolution", "per_minute"}, report))
      (void)setup.control.set("power_on_feed_mode", std::string(*i == 0 ? "G99" : "G98"), "setup");
  }
  if (const auto* node = table.get("start"))
    if (auto p = positionOf(*node, "machine.start", report)) {
      setup.startPosition = *p;
      setup.startGiven = true;
    }
  setup.referencePosition = setup.startPosition;
  if (const auto* node = table.get("reference"))
    if (auto p = positionOf(*node, "machine.reference", report)) setup.referencePosition = *p;
  if (const auto* node = table.get("zero"))
    if (auto p = positionOf(*node, "machine.zero", report)) setup.machineZero = *p;
  if (const auto* node = table.get("second_reference"))
    if (auto p = positionOf(*node, "machine.second_reference", report)) setup.secondReferencePosition = *p;
  if (const auto* node = table.get("rapid")) readRapid(*node, setup.machine, report);
  if (const auto* node = table.get("max_rpm"))
    if (auto v = positiveRate(*node, "machine.max_rpm", "rpm", report)) setup.machine.maxRpm = *v;
  // The older spelling of control.thread_runout.
  if (const auto* node = table.get("thread_runout")) {
    const auto given = std::find_if(setup.control.settings.begin(), setup.control.settings.end(),
                                    [](const interp::ControlSetting& s) { return s.key == "thread_runout"; });
    const auto leads = numberOf(*node);
    if (given != setup.control.settings.end() && given->source != "preset")
      report.at(node->source(), "machine.thread_runout and control.thread_runout both set the thread run-out; give "
                                "control.thread_runout alone");
    else if (!leads || !(*leads >= 0.0) || !(*leads <= 9.9))
      report.at(node->source(), "machine.thread_runout must be a number of leads from 0 to 9.9 (the control's "
                                "G92/G76 run-out parameter, GSK No.19 and Fanuc No.5130 in 0.1 lead), got " +
                                    describe(*node));
    else
      (void)setup.control.set("thread_runout", *leads, "setup");
  }
}

void readSim(const toml::table& table, Setup& setup, Reporter& report) {
  rejectUnknownKeys(table, "sim.", {"voxel", "max_moves", "collisions"}, report);
  if (const auto* node = table.get("voxel"))
    if (auto v = positiveMm(*node, "sim.voxel", report)) setup.voxelMm = *v;
  if (const auto* node = table.get("max_moves")) {
    const auto* integer = node->as_integer();
    if (!integer || integer->get() < 1)
      report.at(node->source(), "sim.max_moves must be a whole number of moves, 1 or more, got " + describe(*node));
    else
      setup.maxMoves = static_cast<std::size_t>(integer->get());
  }
  if (const auto* node = table.get("collisions")) {
    const auto* verdict = node->as_string();
    if (!verdict || (verdict->get() != "error" && verdict->get() != "warn"))
      report.at(node->source(), "sim.collisions must be \"error\" (a collision fails the run) or \"warn\" (it is "
                                "printed and the run succeeds), got " + describe(*node));
    else
      setup.collisionsWarn = verdict->get() == "warn";
  }
}

void readChuck(const toml::table& table, sim::ChuckSpec& chuck, Reporter& report) {
  rejectUnknownKeys(table, "chuck.", {"grip_length", "jaw_diameter", "face_z"}, report);
  if (const auto* node = table.get("grip_length"))
    if (auto v = positiveMm(*node, "chuck.grip_length", report)) chuck.gripLengthMm = *v;
  if (const auto* node = table.get("jaw_diameter"))
    if (auto v = positiveMm(*node, "chuck.jaw_diameter", report)) chuck.jawDiameterMm = *v;
  if (const auto* node = table.get("face_z"))
    if (auto v = finiteMm(*node, "chuck.face_z", report)) chuck.faceZMm = *v;
}

/// One [[tool]] table; `name` is "tool[i]" (1-based, in file order).
std::optional<ToolDefinition> readTool(const toml::table& table, const std::string& name, Reporter& report) {
  std::vector<std::string_view> known{"number", "polygon"};
  known.insert(known.end(), toolShapeKeys().begin(), toolShapeKeys().end());
  rejectUnknownKeys(table, name + ".", known, report);
  ToolDefinition tool{1, defaultOutline(), std::nullopt, 3, 0.0, std::nullopt, {}};
  bool ok = true;
  std::vector<ToolKeyProblem> shapeProblems;
  readToolShape(table, name, tool, shapeProblems);
  for (auto& p : shapeProblems) {
    ok = ok && p.severity != Severity::Error;
    report.at(p.where, std::move(p.message), p.severity, p.columnOffset);
  }

  if (const auto* node = table.get("number")) {
    const auto* integer = node->as_integer();
    if (!integer || integer->get() < 1 || integer->get() > 99) {
      report.at(node->source(), name + ".number must be an integer 1..99, got " + describe(*node));
      ok = false;
    } else {
      tool.number = static_cast<int>(integer->get());
    }
  } else {
    report.at(table.source(), name + " has no number (add number = 1..99)");
    ok = false;
  }

  if (const auto* node = table.get("polygon")) {
    std::vector<RZ> outline;
    bool shapeOk = node->is_array();
    if (const auto* points = node->as_array()) {
      for (const toml::node& point : *points) {
        const auto* pair = point.as_array();
        std::optional<double> r, z;
        if (pair && pair->size() == 2) {
          r = numberOf(*pair->get(0));
          z = numberOf(*pair->get(1));
        }
        if (!r || !z || !std::isfinite(*r) || !std::isfinite(*z)) {
          shapeOk = false;
          break;
        }
        outline.emplace_back(*r, *z);
      }
    }
    if (!shapeOk) {
      report.at(node->source(), name + ".polygon must be a list of [radial, axial] points in mm, got " +
                                    describe(*node));
      ok = false;
    } else {
      auto checked = ConvexPolygon::fromOutline(outline);
      if (checked.polygon) {
        tool.outline = std::move(*checked.polygon);
      } else {
        report.at(node->source(), name + ".polygon " + checked.problem);
        ok = false;
      }
    }
  }
  if (!ok) return std::nullopt;
  tool.facts.source = report.fileName() + ":" + std::to_string(table.source().begin.line) + " " + name;
  return tool;
}

void readTools(const toml::node& node, std::vector<ToolDefinition>& tools, Reporter& report) {
  const auto* array = node.as_array();
  if (array && array->empty()) {
    report.at(node.source(), "tool lists no tools; give at least one [[tool]] or leave tool out");
    return;
  }
  if (!array || !array->is_array_of_tables()) {
    report.at(node.source(), "tool must be given as [[tool]] tables, got " + describe(node));
    return;
  }
  std::vector<ToolDefinition> read;
  std::map<int, std::size_t> seen;  // tool number → 1-based index of its first definition
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto& table = *array->get(i)->as_table();
    const std::string name = "tool[" + std::to_string(i + 1) + "]";
    auto tool = readTool(table, name, report);
    if (!tool) continue;
    const auto [first, inserted] = seen.emplace(tool->number, i + 1);
    if (!inserted) {
      report.at(table.get("number")->source(),
                "tool number " + std::to_string(tool->number) + " is defined twice (tool[" +
                    std::to_string(first->second) + "] and " + name + ")");
      continue;
    }
    read.push_back(std::move(*tool));
  }
  tools = std::move(read);
}

}  // namespace

Setup defaultSetup() {
  Setup setup;
  setup.sourceName = "(default setup)";
  setup.stock = sim::StockSpec{125.0, 112.0, 2.0};
  setup.startPosition = RZ(100.0, 200.0);  // X200 (diameter) Z200
  setup.referencePosition = setup.startPosition;
  setup.voxelMm = std::nullopt;
  setup.control = *interp::controlPreset(interp::kDefaultControlPreset);
  setup.tools.push_back(ToolDefinition{1, defaultOutline(), std::nullopt, 3, 0.0, std::nullopt, {}});
  return setup;
}

interp::TravelLimits travelOf(const Setup& setup) {
  interp::TravelLimits travel;
  const double barLeftZ = setup.stock.faceZMm - setup.stock.lengthMm;
  const auto [xMin, xMax] = setup.travelXDiameterMm.value_or(std::pair{
      -setup.stock.diameterMm, 2.0 * std::max(setup.referencePosition.x(), setup.startPosition.x())});
  const auto [zMin, zMax] = setup.travelZMm.value_or(std::pair{
      barLeftZ - setup.stock.lengthMm, std::max(setup.referencePosition.y(), setup.startPosition.y())});
  travel.xMinDiameterMm = xMin;
  travel.xMaxDiameterMm = xMax;
  travel.zMinMm = zMin;
  travel.zMaxMm = zMax;
  travel.xDerived = !setup.travelXDiameterMm;
  travel.zDerived = !setup.travelZMm;
  return travel;
}

SetupResult parseSetup(std::string_view tomlText, const std::string& fileName) {
  Reporter report(tomlText, fileName);
  toml::table root;
  try {
    root = toml::parse(tomlText, fileName);
  } catch (const toml::parse_error& error) {
    report.at(error.source(), "TOML syntax error: " + std::string(error.description()));
    return {std::nullopt, report.take()};
  }

  Setup setup = defaultSetup();
  setup.sourceName = fileName;
  rejectUnknownKeys(root, "", {"stock", "machine", "control", "sim", "tool", "chuck", "offset", "work_offset", "macro"},
                    report);
  // [control] before [machine]: its preset is what machine.initial_feed_mode modifies.
  if (const auto* node = root.get("control")) {
    if (const auto* table = tableAt(*node, "control", report)) {
      readControl(*table, setup.control, [&report](const toml::source_region& where, std::string message) {
        report.at(where, std::move(message));
      });
      if (table->contains("name")) setup.controlBy = "the setup's [control] name";
    }
  }
  if (const auto* node = root.get("stock")) {
    setup.stockGiven = true;
    // The bar's face is at Z0 unless stated, as with --stock: the default bar's Z2 is the
    // default setup's, not a [stock] table's.
    setup.stock.faceZMm = 0.0;
    if (const auto* table = tableAt(*node, "stock", report))
      readStock(*table, setup, report);
    setup.stockBy = fileName + ":" + std::to_string(node->source().begin.line) + " [stock]";
  }
  if (const auto* node = root.get("machine"))
    if (const auto* table = tableAt(*node, "machine", report)) readMachine(*table, setup, report);
  if (const auto* node = root.get("sim"))
    if (const auto* table = tableAt(*node, "sim", report)) readSim(*table, setup, report);
  if (const auto* node = root.get("tool")) {
    setup.toolsGiven = true;
    readTools(*node, setup.tools, report);
  }
  if (const auto* node = root.get("chuck"))
    if (const auto* table = tableAt(*node, "chuck", report)) readChuck(*table, setup.chuck, report);
  if (setup.chuck.jawDiameterMm && *setup.chuck.jawDiameterMm <= setup.stock.diameterMm)
    report.at(root.get("chuck")->as_table()->get("jaw_diameter")->source(),
              "chuck.jaw_diameter must exceed the stock's diameter (" + floatText(setup.stock.diameterMm) + " mm)");
  if (const auto* node = root.get("offset")) {
    readOffsets(*node, setup.offsets, [&report](const toml::source_region& where, std::string message) {
      report.at(where, std::move(message));
    });
  }

  if (const auto* node = root.get("macro")) {
    readMacroSetup(*node, setup.macro, [&report](const toml::source_region& where, std::string message) {
      report.at(where, std::move(message));
    });
  }
  if (const auto* node = root.get("work_offset")) {
    readWorkOffsets(*node, setup.workOffsets, [&report](const toml::source_region& where, std::string message) {
      report.at(where, std::move(message));
    });
  }

  if (report.hasErrors()) return {std::nullopt, report.take()};
  return {std::move(setup), report.take()};  // warnings only
}

SetupResult loadSetup(const std::filesystem::path& file) {
  const std::string fileName = file.string();
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(file, ec);
  std::ifstream in;
  if (regular) in.open(file, std::ios::binary);
  if (!regular || !in) {
    Diagnostic d;
    d.file = fileName;
    d.message = std::filesystem::exists(file, ec) ? "cannot read the setup file"
                                                   : "setup file not found";
    return {std::nullopt, {std::move(d)}};
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    Diagnostic d;
    d.file = fileName;
    d.message = "cannot read the setup file";
    return {std::nullopt, {std::move(d)}};
  }
  return parseSetup(text.str(), fileName);
}

}  // namespace lathesim::setup
