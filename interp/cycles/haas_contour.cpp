#include "interp/cycles/haas_contour.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

constexpr double kTolMm = 1e-9;

// A G71 level steps in X (a radius, written as a diameter), a G72 level in Z.
double stepOf(const RZ& point, bool turning) { return turning ? point.x() : point.y(); }
double writtenStep(const RZ& point, bool turning) { return turning ? 2.0 * point.x() : point.y(); }

}  // namespace

std::optional<Error> haasContourProblem(const RZ& start, const Contour& contour, bool turning, bool typeII) {
  if (contour.empty()) return std::nullopt;
  const char* cycle = turning ? "G71" : "G72";
  const char axis = turning ? 'X' : 'Z';
  const double towardB = stepOf(contour.front().to, turning) - stepOf(start, turning);
  if (std::abs(towardB) <= kTolMm) return std::nullopt;  // the engine says what is wrong with it
  const double stepDir = towardB > 0 ? 1.0 : -1.0;
  if (!typeII) {
    for (std::size_t i = 1; i < contour.size(); ++i) {
      const ContourSegment& s = contour[i];
      if ((stepOf(s.to, turning) - stepOf(s.from, turning)) * stepDir <= kTolMm) continue;
      return Error{s.line, s.column,
                   fmt::format("{0} type I contour with a pocket: this block moves {1} back toward the P block's {1}. "
                               "A Fanuc alarms here; a Haas roughs such troughs in an order of its own (the material "
                               "above every trough first, then the troughs one by one along Z, as its operator's manual "
                               "shows under \"Troughs\"), which lathesim does not simulate yet; give the P block both X "
                               "and Z (type II) to cut the pocket",
                               cycle, axis)};
    }
  }
  const ContourSegment& last = contour.back();
  if ((stepOf(last.to, turning) - stepOf(start, turning)) * stepDir < -kTolMm) {
    return Error{last.line, last.column,
                 fmt::format("{0} contour ends with a retract past the start point ({1}{2:g} beyond the start's "
                             "{1}{3:g}): the Haas manual asks for a short retraction after a last cut that is not "
                             "monotonic, but no manual at hand says how the roughing passes treat it, so it is not "
                             "simulated; end the contour at or inside the start point and retract after the cycle",
                             cycle, axis, writtenStep(last.to, turning), writtenStep(start, turning))};
  }
  return std::nullopt;
}

}  // namespace lathesim::interp
