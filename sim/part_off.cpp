#include "sim/part_off.hpp"

#include <algorithm>

#include <fmt/format.h>

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
                       inside, off.line)});
      warnedBlock_ = head.block;
    }
  }
  if (removedMm3 <= 0.0) return;  // nothing cut, nothing can have come loose
  // Every cut is checked, and what came loose taken out: the material hung together before
  // this one, so its neighbourhood is enough to see that it parted nothing.
  std::unique_ptr<Stock> piece = stock.takeLoosePieces(changed, revolved.empty());
  if (!piece) return;
  PartOff off{head.line, head.column, deepestZ(group), piece->volumeMm3(), catcherInForce(catchers, first)};
  if (result.part) {
    result.warnings.push_back(
        {head.line, head.column,
         fmt::format("a second piece parts off here ({:.1f} mm³, at Z{:g}): it falls too, and is in neither part.stl "
                     "nor stub.stl; part.stl is the piece that parted off at line {}",
                     off.volumeMm3, off.zMm, result.partOffs.front().line)});
  } else {
    result.part = std::move(piece);
  }
  result.partOffs.push_back(std::move(off));
}

}  // namespace lathesim::sim
