#pragma once
// The setup file (TOML): stock, machine and tools. Its keys are a contract other tools
// rely on; see README.md "Setup file".

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/diagnostic.hpp"
#include "interp/tool_offset.hpp"
#include "sim/stock_spec.hpp"

namespace lathesim::app {

struct ToolDefinition {
  int number = 1;
  ConvexPolygon outline;  // [radial, axial] mm from the programmed point
};

struct Setup {
  std::string sourceName;  // the file it came from, or "(default setup)"
  sim::StockSpec stock;
  RZ startPosition{100.0, 200.0};  // (radius, Z) — the file gives [X diameter, Z]
  std::optional<double> voxelMm;   // [sim] voxel; the command line may override it
  std::vector<ToolDefinition> tools;  // in file order; the first is mounted at start
  interp::ToolOffsets offsets;        // [[offset]] (app/offset_setup.hpp); none by default
};

struct SetupResult {
  std::optional<Setup> setup;
  std::vector<interp::Diagnostic> diagnostics;
};

/// The default: the seed's Φ125×112 bar with its face at Z2, the tool starting clear of it
/// at X200 Z200, and one 80° rhombic-like sharp turning tool numbered 1.
Setup defaultSetup();

SetupResult parseSetup(std::string_view tomlText, const std::string& fileName);
SetupResult loadSetup(const std::filesystem::path& file);

}  // namespace lathesim::app
