#pragma once
// The drawing a part is checked against, as a profile file (TOML): the outline of the turned
// part in the meridian half-plane, dimensioned the way drawings dimension it — X as a
// diameter, Z along the axis, straight lines between points and arcs where a row says so.
//
//   [[profile]]                  # or: profile = [{x = 30, z = 0}, {x = 50, z = -20}, …]
//   x = 30                       # diameter, mm
//   z = 0
//   [[profile]]
//   x = 50
//   z = -20
//   arc = "cw"                   # optional: reach this point by an arc from the previous one,
//   radius = 5                   #   clockwise / counter-clockwise as drawn (Z right, X up),
//                                #   radius > 0 the shorter arc, < 0 the longer one (as G02 R);
//                                #   or center = [x diameter, z] instead of radius
//
// The outline is closed via the axis: from (0, z of the last point) back to (0, z of the
// first point) — unless the last row repeats the first, which closes it as given: a bored
// part, whose section does not reach the axis. See README.md "Checking a part against its
// drawing".

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/diagnostic.hpp"

namespace lathesim::measure {

/// Arcs become chords no further than this from the true arc (mm): far below any voxel.
inline constexpr double kDrawingChordErrorMm = 1e-4;

struct DrawingResult {
  std::optional<std::vector<RZ>> outline;  // (radius, Z) points, arcs as chords; open at the axis
  std::vector<interp::Diagnostic> diagnostics;
};

DrawingResult parseDrawing(std::string_view tomlText, const std::string& fileName);
DrawingResult loadDrawing(const std::filesystem::path& file);

}  // namespace lathesim::measure
