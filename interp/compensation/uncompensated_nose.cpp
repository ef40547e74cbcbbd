// The deviation of a move cut under G40 with a nose radius; see uncompensated_nose.hpp.

#include "interp/compensation/uncompensated_nose.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "geometry/imaginary_tip.hpp"
#include "interp/contour/contour.hpp"
#include "interp/contour/contour_geometry.hpp"

namespace lathesim::interp {
namespace {

constexpr double kSquareTol = 1e-9;  // |s·n| below which the surface tells nothing of the side
constexpr int kArcSamples = 256;     // points along an arc, besides its ends and the worst angle
constexpr double kToldMm = 0.001;    // a deviation below this is not worth a word

// Keeps the deviation of larger size.
void keepWorst(std::optional<NoseDeviation>& worst, double mm) {
  if (!worst || std::abs(mm) > std::abs(worst->mm)) worst = NoseDeviation{mm};
}

}  // namespace

std::optional<NoseDeviation> uncompensatedDeviation(const Move& move, double radiusMm, int tip) {
  if (radiusMm <= 0 || (move.kind != MoveKind::Feed && !isArc(move.kind))) return std::nullopt;
  const RZ s = imaginaryTipDirection(tip);
  const bool centreIsTip = s.squaredNorm() == 0;
  std::optional<NoseDeviation> worst;
  if (!isArc(move.kind)) {
    const RZ along = move.to - move.from;
    if (along.norm() == 0) return std::nullopt;
    const RZ normal = RZ(along.y(), -along.x()) / along.norm();
    const double across = std::abs(s.dot(normal));
    if (!centreIsTip && across < kSquareTol) return std::nullopt;
    keepWorst(worst, radiusMm * (across - 1));
    return worst;
  }
  const ContourSegment arc{move.kind, move.from, move.to, move.center, move.line, move.column};
  const double rho = (move.from - move.center).norm();
  const RZ shift = radiusMm * s;  // Q − O + R·s: the drawn point seen from the moved centre
  const auto at = [&](double angleRad) {
    const RZ q = arcPointAt(arc, angleRad);
    const RZ normal = (q - move.center) / rho;
    if (!centreIsTip && std::abs(s.dot(normal)) < kSquareTol) return;
    keepWorst(worst, std::abs((q - move.center + shift).norm() - rho) - radiusMm);
  };
  const double start = angleAround(move.center, move.from);
  const double sweep = arcSweepRad(arc) * (move.kind == MoveKind::ArcCCW ? 1.0 : -1.0);
  for (int k = 0; k <= kArcSamples; ++k) at(start + sweep * k / kArcSamples);
  if (!centreIsTip) {
    for (const double worstAngle : {std::atan2(s.x(), s.y()), std::atan2(-s.x(), -s.y())}) {
      if (arcPassesAngleInside(arc, worstAngle)) at(worstAngle);
    }
  }
  return worst;
}

void UncompensatedNoseCheck::noteContourPass(int block, const ContourPass& pass) {
  const ContourKey key{pass.first, pass.last};
  (pass.finishes ? finishedAt_ : roughedAt_)[key] = ++passes_;
  if (!pass.finishes) roughedBy_[block] = key;
  if (!pass.finishes && pass.compensated) compensatedBlocks_.insert(block);
}

void UncompensatedNoseCheck::look(const std::vector<Move>& moves) {
  for (const Move& move : moves) {
    if (move.noseComp.side != NoseSide::None || compensatedBlocks_.count(move.block)) continue;
    const bool ofOffset = move.noseComp.radiusMm > 0;
    ToolNose nose{move.noseComp.radiusMm, move.noseComp.tip};
    if (!ofOffset) {
      const auto tool = toolNoses_.find(move.tool);
      if (tool == toolNoses_.end()) continue;
      nose = tool->second;
    }
    const Worst seen{uncompensatedDeviation(move, nose.radiusMm, nose.tip), move, nose, ofOffset};
    const auto roughs = roughedBy_.find(move.block);
    Worst& kept = roughs == roughedBy_.end() ? worst_ : roughing_[roughs->second];
    if (seen.exceeds(kept)) kept = seen;
  }
}

std::optional<Error> UncompensatedNoseCheck::warning() const {
  Worst told = worst_;
  for (const auto& [contour, worst] : roughing_) {
    const auto finished = finishedAt_.find(contour);
    if (finished != finishedAt_.end() && finished->second > roughedAt_.at(contour)) continue;
    if (worst.exceeds(told)) told = worst;
  }
  if (!told.deviation || std::abs(told.deviation->mm) < kToldMm) return std::nullopt;
  const Move& at = told.at;
  const double mm = told.deviation->mm;
  std::string surface;
  if (isArc(at.kind)) {
    surface = fmt::format("R{:g} arc", (at.from - at.center).norm());
  } else {
    const RZ along = at.to - at.from;
    const double degrees = std::atan2(std::abs(along.x()), std::abs(along.y())) * 180 / std::numbers::pi;
    surface = fmt::format("{:.4g}° line", degrees);
  }
  const std::string whose = told.ofOffset ? fmt::format("offset {}", at.toolOffset)
                                      : fmt::format("tool {}'s insert (its offset gives no R)", at.tool);
  return Error{at.line, at.column,
               fmt::format("this contour is cut under G40 with the nose radius R{:g} of {} (tip {}): the finish is "
                           "off the drawing by up to {:.3f} mm normal to the surface, {} on this block's {}; program "
                           "G42 (G41 in a bore) in a G00/G01 move before the contour, or in G70's ns block, with R "
                           "and the tip in the offset (said once, at the worst block)",
                           told.nose.radiusMm, whose, told.nose.tip, std::abs(mm),
                           mm > 0 ? "material left" : "cut into the part", surface)};
}

}  // namespace lathesim::interp
