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
//
// A thread is stated by its callout, not by the outline (which there shows the major
// diameter, as drawings do); its zone is then checked by the callout alone:
//
//   [[thread]]
//   z_range = [-30, 0]           # where it lies along Z
//   pitch = 2                    # mm
//   starts = 1                   # optional (1)
//   hand = "right"               # optional: "right" or "left"
//   major = [29.7, 30.0]         # optional: the diameter's limits [least, greatest], mm
//   minor = [27.4, 27.7]         # optional
//   pitch_diameter = [28.9, 29.3]  # optional
//
// Tolerances. A row may state the tolerance of the line that reaches it from the previous
// row (as `arc` describes that line): on a line parallel to the axis (a diameter) and on a
// face (a length: the face's Z), `tolerance = 0.1` (±), `tolerance = [0, -0.1]` ([upper,
// lower] deviation) or, on a diameter, an ISO 286 fit `tolerance = "h7"` (shaft, lower case)
// or `"H7"` (bore, upper case); on a taper or an arc a number or pair, measured normal to it.
// A line with none takes the general tolerance, ISO 2768-1:
//
//   general_tolerance = "m"      # optional: "f", "m", "c" or "v" (else --general-tolerance, else m)
//   corner_radius = 0.8          # optional: convex corners may be rounded up to this radius (mm)

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/base/diagnostic.hpp"
#include "measure/iso_tolerances.hpp"

namespace lathesim::measure {

/// Arcs become chords no further than this from the true arc (mm): far below any voxel.
inline constexpr double kDrawingChordErrorMm = 1e-4;

/// A diameter's limits, mm.
struct DiameterLimits {
  double least = 0, greatest = 0;
};

struct ThreadCallout {
  int line = 0;  // of its [[thread]] table
  double zLowMm = 0, zHighMm = 0;
  double pitchMm = 0;
  int starts = 1;
  std::optional<bool> rightHand;
  std::optional<DiameterLimits> major, minor, pitchDiameter;
};

/// The line from one profile row to the next, as drawn, with the tolerance its row states.
struct DrawnLine {
  RZ from{0, 0}, to{0, 0};  // (radius, Z)
  int line = 0;             // of the row it reaches
  bool arc = false;
  std::optional<Tolerance> tolerance;
  std::size_t outlineFrom = 0, outlineTo = 0;  // its points in the outline (an arc's chords between)
  bool diameter() const { return !arc && from.x() == to.x() && from.x() > 0 && from.y() != to.y(); }
  bool face() const { return !arc && from.y() == to.y() && from.x() != to.x(); }
};

struct DrawingResult {
  std::optional<std::vector<RZ>> outline;  // (radius, Z) points, arcs as chords; open at the axis
  std::vector<DrawnLine> lines;            // row to row, in the file's order
  std::optional<char> generalTolerance;    // general_tolerance's class: 'f', 'm', 'c' or 'v'
  double cornerRadiusMm = 0;               // corner_radius: convex corners may be rounded to this
  std::vector<ThreadCallout> threads;
  std::vector<interp::Diagnostic> diagnostics;
};

DrawingResult parseDrawing(std::string_view tomlText, const std::string& fileName);
DrawingResult loadDrawing(const std::filesystem::path& file);

}  // namespace lathesim::measure
