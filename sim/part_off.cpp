#include "sim/part_off.hpp"

#include <algorithm>

#include <string>

#include <fmt/format.h>

#include "geometry/meridian_profile.hpp"
#include "sim/cut_rules.hpp"

namespace lathesim::sim {
namespace {

// The Z where the group's cut went deepest: the end of its move nearest the axis (or
// furthest past it), where a parting blade stands when the piece falls.
double deepestZ(std::span<const interp::Move> group) {
  const auto deepest = std::min_element(group.begin(), group.end(),
                                        [](const interp::Move& a, const interp::Move& b) { return a.to.x() < b.to.x(); });
  return deepest->to.y();
}

std::optional<interp::PartsCatcherCommand> catcherInForce(const std::vector<interp::PartsCatcherCommand>& catchers,
                                                          std::size_t move) {
  std::optional<interp::PartsCatcherCommand> inForce;
  for (const auto& command : catchers)
    if (command.movesBefore <= move) inForce = command;
  return inForce;
}

/// The extent of `piece`'s material in its meridian section: from each material sample (φ < 0)
/// its surface lies |φ| away, so the extremes of r ± φ and z ± φ find the faces between samples.
LoosePiece extentOf(const Stock& piece) {
  const SampledSection section = piece.meridianSection();
  LoosePiece extent;
  bool any = false;
  for (int k = 0; k < section.zCount; ++k)
    for (int i = 0; i < section.rCount; ++i) {
      const double phi = section.at(i, k);
      if (phi >= 0.0) continue;
      const double r = i * section.stepMm, z = section.zFirstMm + k * section.stepMm;
      const double inner = std::max(0.0, r + phi), outer = r - phi, low = z + phi, high = z - phi;
      extent.rInnerMm = any ? std::min(extent.rInnerMm, inner) : inner;
      extent.rOuterMm = any ? std::max(extent.rOuterMm, outer) : outer;
      extent.zLowMm = any ? std::min(extent.zLowMm, low) : low;
      extent.zHighMm = any ? std::max(extent.zHighMm, high) : high;
      any = true;
    }
  return extent;
}

/// The material `stock` holds from Z `zLowMm` on, all radii: what stays beside a loose piece.
double materialFrom(const Stock& stock, double zLowMm) {
  const StockSpec& bar = stock.spec();
  const double margin = 4.0 * stock.voxelMm();  // past the bar every way: all of it is counted
  const double rOut = bar.diameterMm / 2.0 + margin, zHigh = bar.faceZMm + margin;
  const std::vector<RZ> box{{0.0, zLowMm}, {rOut, zLowMm}, {rOut, zHigh}, {0.0, zHigh}};
  return stock.materialInside(RevolvedRegion({ConvexPolygon::hullOf(box)}), 0.0);
}

std::string looseMessage(const LoosePiece& p, double voxelMm) {
  const std::string zs = fmt::format("Z{:.1f} to Z{:.1f}", p.zLowMm, p.zHighMm);
  const std::string what =
      p.rInnerMm <= voxelMm
          ? fmt::format("a piece Φ{:.1f} ({}) of {:.1f} mm³", 2.0 * p.rOuterMm, zs, p.volumeMm3)
          : fmt::format("a {:.1f} mm ring (Φ{:.1f} to Φ{:.1f}, {}) of {:.1f} mm³", p.rOuterMm - p.rInnerMm,
                        2.0 * p.rInnerMm, 2.0 * p.rOuterMm, zs, p.volumeMm3);
  const double share = 100.0 * p.volumeMm3 / (p.volumeMm3 + p.beyondMm3);
  return fmt::format("{} comes loose at line {}: it holds {:.0f} % of the material from Z{:.1f} on, {:.1f} mm³ stay "
                     "in the chuck there, so it is no part-off; it falls and is left out of part.stl, and the part "
                     "is what the chuck holds",
                     what, p.line, share, p.zLowMm, p.beyondMm3);
}

}  // namespace

void PartOffWatch::afterCut(std::span<const interp::Move> group, std::size_t first,
                            const std::vector<interp::PartsCatcherCommand>& catchers, const RevolvedRegion& revolved,
                            const std::optional<ChangedArea>& changed, double removedMm3, Stock& stock,
                            SimulationResult& result) {
  const interp::Move& head = group.front();
  const double h = stock.voxelMm();
  if (result.part && interp::isCutting(head.kind) && !revolved.empty() && warnedBlock_ != head.block) {
    // As holder_check measures a holder: material more than a voxel inside, so that a blade
    // withdrawn along the face it parted is not taken for a cut.
    const double inside = result.part->materialInside(revolved, h);
    if (inside > kCollisionVoxels * h * h * h) {
      const PartOff& off = result.partOffs.front();
      result.warnings.push_back(
          {head.line, head.column,
           fmt::format("this block cuts where the part was ({:.1f} mm³ of it), but the part parted off at line {} and "
                       "fell: it is no longer held, so nothing of it is cut; part.stl shows it as it fell",
                       inside, off.line),
           head.source});
      warnedBlock_ = head.block;
    }
  }
  if (removedMm3 <= 0.0) return;  // nothing cut, nothing can have come loose
  // Every cut is checked, and what came loose taken out: the material hung together before
  // this one, so its neighbourhood is enough to see that it parted nothing.
  std::unique_ptr<Stock> piece = stock.takeLoosePieces(changed, revolved.empty());
  if (!piece) return;
  LoosePiece loose = extentOf(*piece);
  loose.line = head.line;
  loose.column = head.column;
  loose.source = head.source;
  loose.volumeMm3 = piece->volumeMm3();
  loose.beyondMm3 = materialFrom(stock, loose.zLowMm);
  if (loose.volumeMm3 <= loose.beyondMm3) {  // not most of what lies there: no part-off
    result.warnings.push_back({head.line, head.column, looseMessage(loose, h), head.source});
    result.loosePieces.push_back(loose);
    return;
  }
  PartOff off{head.line, head.column, deepestZ(group), loose.volumeMm3, catcherInForce(catchers, first), head.source};
  if (result.part) {
    result.warnings.push_back(
        {head.line, head.column,
         fmt::format("a second piece parts off here ({:.1f} mm³, at Z{:g}): it falls too, and is in neither part.stl "
                     "nor stub.stl; part.stl is the piece that parted off at line {}",
                     off.volumeMm3, off.zMm, result.partOffs.front().line),
         head.source});
  } else {
    result.part = std::move(piece);
  }
  result.partOffs.push_back(std::move(off));
}

}  // namespace lathesim::sim
