#include "app/report.hpp"

#include "app/staged_output.hpp"
#include "batch/html_text.hpp"

#include <nlohmann/json.hpp>
#include <cstdio>
#include <string_view>

namespace lathesim::app {
namespace {

using Json = nlohmann::ordered_json;

Json spreadJson(const measure::Spread& s) {
  return {{"mean", s.mean}, {"min", s.min}, {"max", s.max}, {"spread", s.range()}};
}

Json threadJson(const measure::MeasuredThread& thread) {
  const measure::ProgrammedThread& p = thread.programmed;
  const measure::ThreadMeasurement& m = thread.measured;
  Json programmed{{"lead_mm", p.leadMm},
                  {"starts", p.starts},
                  {"hand", p.leadAlongZ ? (p.rightHand ? "right" : "left") : "face"},
                  {"start_angle_deg", p.startAngleDeg},
                  {"root_diameter_mm", 2 * p.rootRadiusMm},
                  {"z_range", {p.zMinMm, p.zMaxMm}}};
  Json measured;
  if (m.problem) {
    measured["problem"] = *m.problem;
  } else {
    measured = {{"angles_deg", m.anglesDeg},
                {"grooves", m.grooves},
                {"z_range", {m.zLowMm, m.zHighMm}},
                {"lead_mm", spreadJson(m.leadMm)},
                {"lead_per_turn_mm", m.leadPerTurnMm},
                {"pitch_mm", spreadJson(m.pitchMm)},
                {"starts", m.starts},
                {"hand", m.rightHand ? "right" : "left"},
                {"start_angle_deg", m.startAngleDeg},
                {"major_diameter_mm", spreadJson(m.majorDiameterMm)},
                {"minor_diameter_mm", spreadJson(m.minorDiameterMm)},
                {"pitch_diameter_mm", spreadJson(m.pitchDiameterMm)},
                {"flank_angles_deg", {{"left", spreadJson(m.leftFlankDeg)}, {"right", spreadJson(m.rightFlankDeg)}}}};
  }
  return {{"line", p.line},
          {"column", p.column},
          {"code", p.code},
          {"kind", p.internal ? "internal" : "external"},
          {"programmed", programmed},
          {"measured", measured}};
}

nlohmann::ordered_json valueJson(const interp::ParameterValue& value) {
  if (const auto* name = std::get_if<std::string>(&value)) return *name;
  if (const auto* number = std::get_if<double>(&value)) return *number;
  return std::get<std::vector<std::string>>(value);
}

nlohmann::ordered_json controlJson(const interp::Control& control) {
  nlohmann::ordered_json parameters;
  for (const auto& s : control.settings)
    parameters[s.key] = {{"value", valueJson(s.value)}, {"manual", s.manual}, {"verified", s.verified}, {"set_by", s.source}};
  return {{"preset", control.preset}, {"parameters", parameters}};
}

// The first part-off (later ones are warnings), or null.
nlohmann::ordered_json partedOffJson(const RunFigures& f) {
  if (f.simulation.partOffs.empty()) return nullptr;
  const sim::PartOff& off = f.simulation.partOffs.front();
  nlohmann::ordered_json catcher = nullptr;
  if (off.catcher)
    catcher = {{"line", off.catcher->line}, {"column", off.catcher->column}, {"code", off.catcher->code},
               {"in_place", off.catcher->inPlace}};
  return {{"line", off.line},
          {"column", off.column},
          {"z", off.zMm},
          {"volume_mm3", off.volumeMm3},
          {"stub_volume_mm3", f.stubVolumeMm3},
          {"stub_mesh_volume_mm3", f.stubMeshVolumeMm3},
          {"parts_catcher", catcher}};
}

}  // namespace

nlohmann::ordered_json machineAssumedJson(const std::vector<setup::MachineAssumption>& assumed) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const setup::MachineAssumption& a : assumed) {
    json[a.key] = a.values.size() == 1 ? nlohmann::ordered_json(a.values[0]) : nlohmann::ordered_json(a.values);
  }
  return json;
}

std::string threadSummary(const measure::MeasuredThread& thread) {
  const measure::ProgrammedThread& p = thread.programmed;
  const measure::ThreadMeasurement& m = thread.measured;
  std::string line = "thread, line " + std::to_string(p.line) + " (" + p.code + ", " +
                     (p.internal ? "internal" : "external") + "): programmed lead " + batch::fixed(p.leadMm, 4) + " mm, " +
                     std::to_string(p.starts) + (p.starts == 1 ? " start, " : " starts, ") +
                     (p.leadAlongZ ? (p.rightHand ? "right" : "left") : "face") + "-hand; ";
  if (m.problem) return line + "not measured: " + *m.problem;
  return line + "measured lead " + batch::fixed(m.leadMm.mean, 4) + " mm (±" + batch::fixed(m.leadMm.range() / 2, 4) + " over " +
         std::to_string(m.anglesDeg.size()) + " angles), " + std::to_string(m.starts) +
         (m.starts == 1 ? " start, " : " starts, ") + (m.rightHand ? "right" : "left") + "-hand, major Φ" +
         batch::fixed(m.majorDiameterMm.mean, 3) + ", minor Φ" + batch::fixed(m.minorDiameterMm.mean, 3) + " (programmed root Φ" +
         batch::fixed(2 * p.rootRadiusMm, 3) + "), pitch Φ" + batch::fixed(m.pitchDiameterMm.mean, 3) + ", flanks " +
         batch::fixed(m.leftFlankDeg.mean, 1) + "°/" + batch::fixed(m.rightFlankDeg.mean, 1) + "°";
}

std::string skippedSummary(const std::vector<interp::SkippedBlock>& skipped) {
  if (skipped.empty()) return "";
  constexpr std::size_t kLinesNamed = 10;  // the rest are in report.json
  std::string lines;
  for (std::size_t i = 0; i < skipped.size() && i < kLinesNamed; ++i)
    lines += (i == 0 ? "" : ", ") + std::to_string(skipped[i].line);
  if (skipped.size() > kLinesNamed) lines += ", …";
  return std::to_string(skipped.size()) + (skipped.size() == 1 ? " block" : " blocks") + " skipped by '/' (line" +
         (skipped.size() == 1 ? " " : "s ") + lines + "), ";
}

nlohmann::ordered_json reportJson(const RunFigures& f) {
  nlohmann::ordered_json report;
  report["program"] = f.program;
  report["setup"] = f.setup;
  report["control"] = controlJson(f.control);
  report["machine"] = {{"dialect", interp::dialectName(f.machine.dialect)},
                       {"control", f.machine.control},
                       {"inferred", f.machine.inferred()},
                       {"because", f.machine.because},
                       {"conflicts", f.machine.conflicts}};
  const auto source = [](bool derived, const char* key) {
    return derived ? std::string("derived from [machine] reference and start and the bar") : "[machine] " + std::string(key);
  };
  report["travel"] = {{"x_diameter_mm", {f.travel.xMinDiameterMm, f.travel.xMaxDiameterMm}},
                      {"z_mm", {f.travel.zMinMm, f.travel.zMaxMm}},
                      {"x_from", source(f.travel.xDerived, "travel_x")},
                      {"z_from", source(f.travel.zDerived, "travel_z")}};
  report["machine"]["assumed"] = machineAssumedJson(f.assumed);
  report["stock"] = f.stock;
  report["tools"] = f.tools;
  report["voxel_mm"] = f.voxelMm;
  if (f.atLine) report["at_line"] = *f.atLine;
  report["stock_volume_mm3"] = f.stockVolumeMm3;
  report["final_volume_mm3"] = f.finalVolumeMm3;
  report["removed_volume_mm3"] = f.stockVolumeMm3 - f.finalVolumeMm3;
  report["parted_off"] = partedOffJson(f);
  // Pieces a cut set loose that were no part-off (sim/part_off.hpp): they fell, and are in no mesh.
  auto& loose = report["loose_pieces"] = nlohmann::ordered_json::array();
  for (const auto& p : f.simulation.loosePieces)
    loose.push_back({{"line", p.line},
                     {"column", p.column},
                     {"volume_mm3", p.volumeMm3},
                     {"diameter_mm", {2.0 * p.rInnerMm, 2.0 * p.rOuterMm}},
                     {"z_mm", {p.zLowMm, p.zHighMm}},
                     {"staying_beyond_mm3", p.beyondMm3}});
  report["mesh_volume_mm3"] = f.meshVolumeMm3;
  report["volume_tolerance_mm3"] = f.volumeToleranceMm3;
  report["mesh_crumbs"] = {{"count", f.meshCrumbs.count}, {"volume_mm3", f.meshCrumbs.volumeMm3}};
  report["mesh_triangles"] = f.meshTriangles;
  report["moves"] = f.moves;
  report["cycle_time_s"] = f.cycleTimeS;
  auto& collisions = report["collisions"] = nlohmann::ordered_json::array();
  for (std::size_t n = 0; n < f.simulation.collisions.size(); ++n) {
    const sim::Collision& c = f.simulation.collisions[n];
    const interp::Diagnostic* said = n < f.collisions.size() ? &f.collisions[n] : nullptr;
    collisions.push_back({{"file", said ? said->file : f.program},
                          {"line", c.line},
                          {"column", c.column},
                          {"block", said ? said->sourceLine : std::string()},
                          {"kind", c.kind},
                          {"volume_mm3", c.volumeMm3},
                          {"tool", c.tool},
                          {"position", {{"x_diameter_mm", 2.0 * c.at.x()}, {"z_mm", c.at.y()}}},
                          {"severity", said && said->severity == interp::Severity::Warning ? "warning" : "error"},
                          {"message", said ? said->message : std::string()}});
  }
  report["blocks"] = nlohmann::ordered_json::array();  // its rows are streamed by writeReport
  auto& threads = report["threads"] = nlohmann::ordered_json::array();
  for (const auto& t : f.threads) threads.push_back(threadJson(t));
  auto& stops = report["stops"] = nlohmann::ordered_json::array();
  for (const auto& s : f.stops) stops.push_back({{"line", s.line}, {"column", s.column}, {"code", s.code}});
  auto& skipped = report["skipped_blocks"] = nlohmann::ordered_json::array();
  for (const auto& s : f.skipped) {
    skipped.push_back({{"line", s.line}, {"column", s.column}});
    if (!s.file.empty()) skipped.back()["file"] = s.file;
  }
  auto& warnings = report["warnings"] = nlohmann::ordered_json::array();
  for (const auto& w : f.warnings) warnings.push_back({{"line", w.line}, {"column", w.column}, {"message", w.message}});
  auto& notes = report["notes"] = nlohmann::ordered_json::array();
  for (const auto& n : f.notes) {
    notes.push_back({{"line", n.line}, {"column", n.column}, {"message", n.message}});
    if (n.file != f.program) notes.back()["file"] = n.file;  // a subprogram's own file (M98 from a file)
  }
  report["peak_memory_mb"] = f.peakMemoryMb;
  report["grid_memory_mb"] = f.gridMemoryMb;
  report["timing_s"] = {{"parse", f.timing.parseS},
                        {"simulate", f.timing.simulateS},
                        {"mesh", f.timing.meshS},
                        {"render", f.timing.renderS},
                        {"bar", f.timing.barS},
                        {"write", f.timing.writeS},
                        {"total", f.timing.totalS}};
  if (f.timing.animateS > 0) report["timing_s"]["animate"] = f.timing.animateS;
  if (f.timing.stepsS > 0) report["timing_s"]["steps"] = f.timing.stepsS;
  return report;
}


namespace {

constexpr auto kReplaceInvalidUtf8 = nlohmann::ordered_json::error_handler_t::replace;

/// `value` as nlohmann's dump(2) writes it at `indent` inside its parent.
void writeIndented(std::ostream& out, const nlohmann::ordered_json& value, std::string_view indent) {
  for (const char c : value.dump(2, ' ', false, kReplaceInvalidUtf8)) {
    out.put(c);
    if (c == '\n') out << indent;
  }
}

}  // namespace

// The top level written here, key by key, as dump(2) would: the block rows, which may be
// millions, are written one by one from `blocks` where the report holds an empty array.
void writeReport(const nlohmann::ordered_json& report, const sim::BlockRows& blocks, const std::filesystem::path& file) {
  writeTextFile(file, [&](std::ostream& out) {
    out << '{';
    bool firstKey = true;
    for (const auto& [key, value] : report.items()) {
      out << (firstKey ? "\n  " : ",\n  ") << nlohmann::ordered_json(key).dump(-1, ' ', false, kReplaceInvalidUtf8) << ": ";
      firstKey = false;
      if (key != "blocks") {
        // Text a program quoted (a comment in a note) need not be UTF-8: such bytes become U+FFFD.
        writeIndented(out, value, "  ");
        continue;
      }
      bool firstRow = true;
      blocks.forEach([&](const sim::BlockRemoval& b) {
        out << (firstRow ? "[\n    " : ",\n    ");
        firstRow = false;
        writeIndented(out, {{"line", b.line}, {"column", b.column}, {"removed_volume_mm3", b.removedMm3}, {"time_s", b.timeS}},
                      "    ");
      });
      out << (firstRow ? "[]" : "\n  ]");
    }
    out << (firstKey ? "}\n" : "\n}\n");
  });
}

}  // namespace lathesim::app
