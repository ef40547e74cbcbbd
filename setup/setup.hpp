#pragma once
// The setup file (TOML): stock, machine and tools. Its keys are a contract other tools
// rely on; see README.md "Setup file".

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/base/diagnostic.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/control/dialect.hpp"
#include "interp/control/machine_limits.hpp"
#include "interp/interpreter.hpp"
#include "interp/base/move.hpp"
#include "interp/compensation/tool_offset.hpp"
#include "interp/state/work_frame.hpp"
#include "setup/macro_setup.hpp"
#include "setup/tailstock_setup.hpp"
#include "setup/tool_facts.hpp"
#include "sim/stock_spec.hpp"
#include "sim/chuck_spec.hpp"  // after stock_spec: the chuck is placed on the bar

namespace lathesim::setup {

struct ToolDefinition {
  int number = 1;
  ConvexPolygon outline;  // the cutter: [radial, axial] mm from the programmed point; swept and removed
  std::optional<ConvexPolygon> holderBody;  // catalogue tools: the holder's head and shank; never cuts
  int tipNumber = 3;          // Fanuc imaginary tip 0–9: the programmed point relative to the nose
  double noseRadiusMm = 0.0;  // 0 for a polygon tool
  // The insert's thickness across the tool's plane (mm): what a cut made with the spindle
  // stopped removes across it. `thickness`, or an ISO insert's own; unset: sim's default.
  std::optional<double> thicknessMm;
  ToolFacts facts;  // what it is and where it came from, for the tool table (tool_facts.hpp)
};

struct Setup {
  std::string sourceName;  // the file it came from, or "(default setup)"
  sim::StockSpec stock;
  bool stockGiven = false;  // the file has [stock]: a bar the program states is not used
  // Who stated the bar, for report.json's "stock": "setup.toml:3 [stock]", "--stock D40xL80",
  // "the program at prog.nc:2: (STOCK D40 L80)"; "" when the default setup's bar is assumed.
  std::string stockBy;
  std::string stockMaterial;  // [stock] material, as written; "" when not stated
  bool stockFaceGiven = false;  // stock.face_z (or --stock …xZ) stated; else the face is at Z0
                                // with a [stock] or --stock, Z2 with the default bar
  RZ startPosition{100.0, 200.0};  // (radius, Z) — the file gives [X diameter, Z]
  bool startGiven = false;         // [machine] start stated; else X200 Z200 is assumed
  RZ referencePosition{100.0, 200.0};  // G28's reference point (radius, Z); the start if not given
  interp::MachineLimits machine;       // [machine] rapid = [X, Z] mm/min, max_rpm (travel: travelOf)
  std::optional<std::pair<double, double>> travelXDiameterMm;  // [machine] travel_x = [min, max], diameters
  std::optional<std::pair<double, double>> travelZMm;          // [machine] travel_z = [min, max]
  interp::Dialect dialect = interp::Dialect::FanucA;  // [machine] dialect: how codes are written
  // Who stated the dialect and the control's preset ("--dialect", "the setup's [machine]
  // dialect"), or "" when nobody did and the program's evidence chooses (machine_choice.hpp).
  std::string dialectBy;
  std::string controlBy;
  interp::Control control;  // [control]: the preset and its parameters, how the machine behaves
                            // ([machine] initial_feed_mode is control.power_on_feed_mode,
                            // [machine] thread_runout control.thread_runout)
  std::optional<double> voxelMm;   // [sim] voxel; the command line may override it
  std::size_t maxMoves = interp::kDefaultMaxMoves;  // [sim] max_moves, --max-moves: more is an error
  // [sim] collisions = "warn", --collisions warn: a collision is printed as a warning and the
  // run succeeds; by default ("error") it is an error and the command exits kExitCrash.
  bool collisionsWarn = false;
  std::vector<ToolDefinition> tools;  // in file order; the first is mounted at start
  bool toolsGiven = false;  // the file lists [[tool]]s (else tool 1 is the default placeholder)
  sim::ChuckSpec chuck;               // [chuck]: jaws on the bar's left end
  std::optional<Tailstock> tailstock;  // [machine] tailstock; none by default
  interp::ToolOffsets offsets;        // [[offset]] (setup/offset_setup.hpp); none by default
  interp::WorkOffsets workOffsets = interp::zeroWorkOffsets();  // [[work_offset]]: G54–G59
  std::optional<RZ> machineZero;      // [machine] zero: G53's zero (radius, Z); unset: the reference point
  std::optional<RZ> secondReferencePosition;  // [machine] second_reference: G30's point (radius, Z)
  MacroSetup macro;                   // [macro] (setup/macro_setup.hpp): step limit, variables
};

/// The voxel size used when neither --voxel nor [sim] voxel says: the default part runs in
/// about a second with it, and volumes come within a few hundredths of a percent.
inline constexpr double kDefaultVoxelMm = 0.2;

struct SetupResult {
  std::optional<Setup> setup;
  std::vector<interp::Diagnostic> diagnostics;
};

/// The default: the seed's Φ125×112 bar with its face at Z2, the tool starting clear of it
/// at X200 Z200, and one 80° rhombic-like sharp turning tool numbered 1.
Setup defaultSetup();

/// The machine's travel: what [machine] travel_x / travel_z state, and for an axis they leave
/// out, derived: X from minus the bar's diameter (the tool may pass the axis) to the reference
/// point's or the start's X, whichever is larger; Z from one bar length behind the bar's left
/// end to the reference point's or the start's Z. The reference point is where a lathe's axes
/// end; a setup whose machine travels further says so.
interp::TravelLimits travelOf(const Setup& setup);

SetupResult parseSetup(std::string_view tomlText, const std::string& fileName);
SetupResult loadSetup(const std::filesystem::path& file);

}  // namespace lathesim::setup
