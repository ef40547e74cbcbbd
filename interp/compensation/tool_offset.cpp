// Tool offsets: the shift of the tip and the R and tip number for G41/G42; see tool_offset.hpp.

#include "interp/compensation/tool_offset.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

RZ offsetShift(const ToolOffsets& offsets, int number) {
  const auto found = offsets.find(number);
  if (number == 0 || found == offsets.end()) return RZ(0, 0);
  const ToolOffset& o = found->second;
  return RZ((o.xDiameterMm + o.wearXDiameterMm) / 2.0, o.zMm + o.wearZMm);
}

NoseComp noseCompWith(NoseSide side, const ToolOffsets& offsets, int number) {
  const auto found = offsets.find(number);
  if (number == 0 || found == offsets.end()) return NoseComp{side, 0.0, 0};
  return NoseComp{side, found->second.radiusMm, found->second.tip};
}

Status applyToolOffsets(std::vector<Move>& moves, const ToolOffsets& offsets) {
  RZ inForce(0, 0);  // the shift the tool stands under
  for (Move& move : moves) {
    if (move.kind == MoveKind::Dwell) {
      move.from += inForce;
      move.to += inForce;
      continue;
    }
    const RZ own = offsetShift(offsets, move.toolOffset);
    if (isArc(move.kind) && own != inForce) {
      return Error{move.line, move.column,
                   fmt::format("the tool offset changes to {} in an arc block: the new offset "
                               "takes effect with the block's move, which must then be G00 or "
                               "G01; change the offset (T word) before a straight move",
                               move.toolOffset)};
    }
    move.from += inForce;
    move.to += own;
    if (isArc(move.kind)) move.center += own;
    inForce = own;
  }
  return success();
}

}  // namespace lathesim::interp
