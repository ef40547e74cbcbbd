#include "interp/motion/g28_return.hpp"

namespace lathesim::interp {

std::vector<CycleLeg> referenceReturnLegs(const RZ& position, std::optional<double> intermediateRadiusMm,
                                          std::optional<double> intermediateZMm, const RZ& reference) {
  RZ intermediate = position;
  RZ end = position;
  if (intermediateRadiusMm) {
    intermediate.x() = *intermediateRadiusMm;
    end.x() = reference.x();
  }
  if (intermediateZMm) {
    intermediate.y() = *intermediateZMm;
    end.y() = reference.y();
  }
  return keptLegs({{MoveKind::Rapid, position, intermediate, 1, {0, 0}},
                   {MoveKind::Rapid, intermediate, end, 2, {0, 0}}});
}

}  // namespace lathesim::interp
