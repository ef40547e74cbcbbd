#pragma once
// report.json: what a run measured, for people and for other tools.

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "geometry/mesh_shells.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/text/machine_choice.hpp"
#include "interp/control/machine_limits.hpp"
#include "interp/base/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "setup/machine_assumptions.hpp"
#include "measure/thread_measure.hpp"
#include "interp/base/move.hpp"
#include "sim/block_rows.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

/// Each step's own wall time (s). Steps that run beside each other overlap (stock.vdb is
/// written while the part is meshed, the pictures drawn while the files are written), so they
/// add up to more than totalS.
struct RunTimings {
  double parseS = 0, simulateS = 0, meshS = 0, renderS = 0;
  double barS = 0;      // building the bar's level set once (the floor), a part of simulateS
  double writeS = 0;    // writing the files, each writer's own time added (the pictures' in renderS)
  double totalS = 0;    // the whole command, from its start to report.json staged
  double animateS = 0;  // --animate: drawing and encoding the frames (not counted in simulateS)
  double stepsS = 0;    // report.html's stepping: taking the stock's sections (not counted in simulateS)
};

struct RunFigures {
  std::string program;
  std::string setup;
  interp::Control control;  // the preset and every parameter in force
  interp::MachineChoice machine;  // the dialect and control, stated or read from the program, and why
  interp::TravelLimits travel;  // the machine's travel the moves were checked against
  std::vector<setup::MachineAssumption> assumed;  // what the setup did not say of the machine
  double voxelMm = 0;
  std::optional<int> atLine;  // --at-line: the run stopped after this line's first execution
  double stockVolumeMm3 = 0;  // measured on the level set of the untouched bar
  double finalVolumeMm3 = 0;  // measured on the level set after the program
  double meshVolumeMm3 = 0;   // part.stl's enclosed volume, as a cross-check
  double stubVolumeMm3 = 0;      // after a part-off: the stub's level set (final volume: stub + pieces)
  double stubMeshVolumeMm3 = 0;  // and stub.stl's enclosed volume
  double volumeToleranceMm3 = 0;  // how far the part's volumes may stray (sim::volumeToleranceMm3)
  DroppedCrumbs meshCrumbs;       // sub-voxel shells left out of the exported mesh
  std::size_t meshTriangles = 0;
  std::size_t moves = 0;
  double cycleTimeS = 0;  // the machine time of all moves (interp/motion/cycle_time.hpp)
  double peakMemoryMb = 0;  // this process's peak resident memory (the Xvfb it may start is not counted)
  double gridMemoryMb = 0;  // the level sets' own memory: the bar's, or after the program (with a parted-off piece) if more
  sim::SimulationResult simulation;
  std::vector<measure::MeasuredThread> threads;  // every thread cut, as programmed and as measured
  std::vector<interp::ProgramStop> stops;  // M00/M01 reached: listed, not timed
  std::vector<interp::SkippedBlock> skipped;  // '/' blocks passed over under block delete
  std::vector<interp::Diagnostic> warnings;
  std::vector<interp::Diagnostic> notes;
  nlohmann::ordered_json tools = nlohmann::ordered_json::array();  // the tool table (tool_table.hpp)
  std::vector<int> toolsUsed;  // the tool numbers the moves used, in the order of first use
  nlohmann::ordered_json stock = nlohmann::ordered_json::object();  // the bar and who stated it
  // simulation.collisions' diagnostics, one each in the same order: errors, or warnings under
  // [sim] collisions = "warn" (collision_diagnostics.hpp).
  std::vector<interp::Diagnostic> collisions;
  RunTimings timing;

  /// The run crashed, and the setup does not let a crash pass: exit status setup::kExitCrash.
  bool crashed() const {
    return std::any_of(collisions.begin(), collisions.end(),
                       [](const interp::Diagnostic& d) { return d.severity == interp::Severity::Error; });
  }
};

/// The report as JSON, for commands that add their own section (check adds "check"), with
/// `blocks` empty: writeReport writes its rows one by one (a row as a JSON tree takes
/// hundreds of bytes, and a long program has a row a block).
nlohmann::ordered_json reportJson(const RunFigures& figures);

/// report.json's "machine": {"assumed": {…}}: each assumption by its key, a number or a list
/// of mm ("start": [200, 200], "stock_face_z": 0); an empty object when the setup said all.
nlohmann::ordered_json machineAssumedJson(const std::vector<setup::MachineAssumption>& assumed);

/// One line for the terminal naming a thread and what was measured of it.
std::string threadSummary(const measure::MeasuredThread& thread);

/// "2 blocks skipped by '/' (lines 5, 9), " for the summary line; "" when none was.
std::string skippedSummary(const std::vector<interp::SkippedBlock>& skipped);

/// Writes report.json: `report` (reportJson's), its `blocks` filled with a row for each of
/// `blocks`, as if they had been in the tree.
void writeReport(const nlohmann::ordered_json& report, const sim::BlockRows& blocks, const std::filesystem::path& file);

}  // namespace lathesim::app
