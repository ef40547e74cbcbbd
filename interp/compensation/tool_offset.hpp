#pragma once
// Tool offsets: the setup's [[offset]] table, selected by the T word (T0101: tool 1, offset 1;
// offset 0 cancels). An offset shifts where the tool's imaginary tip lands relative to the
// programmed point — what a mis-set or worn offset does to the part — and carries the nose
// radius R and imaginary tip number that G41/G42 compensate with (the offset table's, as on a
// Fanuc control, not the insert's). An offset number the setup does not define acts as an
// all-zero offset: no shift, R 0, tip 0 (no error, as on a machine whose entry is zero).

#include <map>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/base/move.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

struct ToolOffset {
  double xDiameterMm = 0;      // geometry shift in X, a diameter
  double zMm = 0;              // geometry shift in Z
  double radiusMm = 0;         // nose radius R, ≥ 0
  int tip = 0;                 // imaginary tip number 0–9 (lathe-cycles.md §8)
  double wearXDiameterMm = 0;  // wear shift in X, a diameter
  double wearZMm = 0;          // wear shift in Z
  double wearRadiusMm = 0;     // wear of the nose radius; G41/G42 use radius + wear (G10 P1–64 R)
};

using ToolOffsets = std::map<int, ToolOffset>;  // offset number (1–99) → offset

/// Offset `number` of the table: all zero for 0 and for an undefined number.
ToolOffset offsetNumbered(const ToolOffsets& offsets, int number);

/// Where the tip lands relative to the programmed point: ((x + wear_x)/2, z + wear_z), a
/// radius and a Z.
RZ offsetShift(const ToolOffset& offset);
RZ offsetShift(const ToolOffsets& offsets, int number);

/// The compensation `side` in force with `offset`: its R (+ wear) and tip.
NoseComp noseCompWith(NoseSide side, const ToolOffset& offset);

/// Moves every move of `moves` by its offsetShift, as the machine does: a move ends at its
/// programmed end plus its own offset's shift, and starts at its programmed start plus the
/// shift the tool was under until then (the previous move's; `shiftInForce` before the first,
/// zero at the program's start). A changed offset therefore takes effect with the next move,
/// which must be straight: an arc whose offset shift differs from the one in force is an error
/// at its block. A dwell stays where the tool is. `shiftInForce` is left as the last move's,
/// for the moves that follow (the toolpath goes through in pieces: move_pipeline.hpp).
Status applyToolOffsets(std::vector<Move>& moves, RZ& shiftInForce);

}  // namespace lathesim::interp
