#include "interp/motion/travel_limits.hpp"

#include <numbers>
#include <string>

#include <fmt/format.h>

#include "interp/base/tolerance.hpp"
#include "interp/contour/contour_geometry.hpp"
#include "interp/output/toolpath_csv.hpp"

namespace lathesim::interp {
namespace {

// The points of the move where it reaches furthest along each axis: its ends, and the
// arc's extremes between them.
std::vector<RZ> reachedPoints(const Move& move) {
  std::vector<RZ> points{move.from, move.to};
  if (!isArc(move.kind)) return points;
  const ContourSegment arc{move.kind, move.from, move.to, move.center, move.line, move.column};
  for (const double angle : {0.0, std::numbers::pi / 2, std::numbers::pi, -std::numbers::pi / 2})
    if (arcPassesAngleInside(arc, angle)) points.push_back(arcPointAt(arc, angle));
  return points;
}

std::string limitsText(const TravelLimits& t, bool xAxis) {
  const bool derived = xAxis ? t.xDerived : t.zDerived;
  const std::string range = xAxis ? fmt::format("X{} to X{}", csvNumber(t.xMinDiameterMm), csvNumber(t.xMaxDiameterMm))
                                  : fmt::format("Z{} to Z{}", csvNumber(t.zMinMm), csvNumber(t.zMaxMm));
  if (!derived) return fmt::format("{} ([machine] travel_{})", range, xAxis ? 'x' : 'z');
  return fmt::format("{}, derived from [machine] reference and start and the bar, as no setup states it: an "
                     "assumption, not checked further on this axis; give [machine] travel_{} to have it checked",
                     range, xAxis ? 'x' : 'z');
}

std::string beyondText(double x, double z, bool xAxis, const TravelLimits& travel) {
  return fmt::format("overtravel: this block moves the tool to X{} Z{} (in the setup's frame), beyond the machine's "
                     "{} travel, {}",
                     csvNumber(x), csvNumber(z), xAxis ? 'X' : 'Z', limitsText(travel, xAxis));
}

}  // namespace

Status checkTravel(const std::vector<Move>& moves, const TravelLimits& travel, DerivedTravelWarned& warned,
                   std::vector<Error>& warnings) {
  for (const Move& move : moves) {
    for (const RZ& point : reachedPoints(move)) {
      const double x = diameterOf(point);
      const bool xOut = x < travel.xMinDiameterMm - kTolMm || x > travel.xMaxDiameterMm + kTolMm;
      const bool zOut = point.y() < travel.zMinMm - kTolMm || point.y() > travel.zMaxMm + kTolMm;
      // A stated travel stops the program; a derived one is said once per axis.
      for (const bool xAxis : {true, false}) {
        if (!(xAxis ? xOut : zOut)) continue;
        if (!(xAxis ? travel.xDerived : travel.zDerived))
          return Error{move.line, move.column, beyondText(x, point.y(), xAxis, travel)};
        bool& said = xAxis ? warned.x : warned.z;
        if (said) continue;
        said = true;
        warnings.push_back(Error{move.line, move.column, beyondText(x, point.y(), xAxis, travel)});
      }
    }
  }
  return success();
}

}  // namespace lathesim::interp
