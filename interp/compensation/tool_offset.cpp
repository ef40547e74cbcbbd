// Tool offsets: the shift of the tip and the R and tip number for G41/G42; see tool_offset.hpp.

#include "interp/compensation/tool_offset.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

ToolOffset offsetNumbered(const ToolOffsets& offsets, int number) {
  const auto found = offsets.find(number);
  if (number == 0 || found == offsets.end()) return ToolOffset{};
  return found->second;
}

RZ offsetShift(const ToolOffset& o) {
  return RZ((o.xDiameterMm + o.wearXDiameterMm) / 2.0, o.zMm + o.wearZMm);
}

RZ offsetShift(const ToolOffsets& offsets, int number) { return offsetShift(offsetNumbered(offsets, number)); }

NoseComp noseCompWith(NoseSide side, const ToolOffset& offset) {
  return NoseComp{side, offset.radiusMm + offset.wearRadiusMm, offset.tip};
}

Status applyToolOffsets(std::vector<Move>& moves, RZ& inForce) {
  for (Move& move : moves) {
    if (move.kind == MoveKind::Dwell) {
      move.from += inForce;
      move.to += inForce;
      continue;
    }
    const RZ own = move.offsetShift;
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
