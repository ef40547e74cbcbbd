#include "interp/execution/work_coordinates.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "interp/text/word_units.hpp"

namespace lathesim::interp {

void selectWorkSystem(const Code& code, ModalState& state) {
  WorkFrame frame = state.frame;
  frame.system = code.number - 53;
  state.position -= frame.shift() - state.frame.shift();
  state.frame = frame;
}

void changeWorkOffsets(const WorkOffsets& offsets, ModalState& state) {
  WorkFrame frame = state.frame;
  frame.offsets = offsets;
  state.position -= frame.shift() - state.frame.shift();
  state.frame = frame;
}

Result<RZ> machineCoordinateTarget(ParsedBlock& block, const Code& g53, const ModalState& state,
                                   const InterpreterOptions& options) {
  for (char letter : {'U', 'W'}) {
    if (const auto word = block.take(letter)) {
      return Error{block.line, word->column,
                   fmt::format("{} in a G53 block: G53 goes to machine coordinates, which are "
                               "absolute; give X and/or Z",
                               word->text())};
    }
  }
  if (state.incremental) {
    return Error{block.line, g53.column,
                 "G53 under G91: machine coordinates are absolute; select G90 before G53"};
  }
  const auto x = block.take('X');
  const auto z = block.take('Z');
  if (!x && !z) {
    return Error{block.line, g53.column,
                 "G53 needs X and/or Z: the machine coordinates to go to (G53 X0 Z0 goes to "
                 "machine zero)"};
  }
  const RZ zero = options.machineZero.value_or(options.referencePosition.value_or(options.startPosition));
  const RZ shift = state.frame.shift();
  RZ world = state.position + shift;  // the setup's frame
  const NumberReading reading = NumberReading::of(options.control, state.inch);
  if (x) world.x() = zero.x() + lengthMm(*x, reading) / 2.0;
  if (z) world.y() = zero.y() + lengthMm(*z, reading);
  return RZ(world - shift);
}

}  // namespace lathesim::interp
