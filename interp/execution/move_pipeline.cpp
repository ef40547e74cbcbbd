#include "interp/execution/move_pipeline.hpp"

#include <utility>

#include "interp/compensation/nose_compensation.hpp"
#include "interp/compensation/tool_offset.hpp"
#include "interp/state/move_limit.hpp"
#include "interp/motion/corners.hpp"
#include "interp/motion/rapid_path.hpp"
#include "interp/motion/travel_limits.hpp"

namespace lathesim::interp {
namespace {

// Each move from its work coordinate system into the setup's frame. A change of system
// re-expresses the position (work_coordinates.cpp), so consecutive moves stay joined.
void placeInSetupFrame(std::vector<Move>& moves) {
  for (Move& move : moves) {
    move.from += move.workShift;
    move.to += move.workShift;
    if (isArc(move.kind)) move.center += move.workShift;
  }
}

}  // namespace

MovePipeline::MovePipeline(const InterpreterOptions& options, MoveSink& sink, std::vector<Error>& warnings)
    : options_(options), sink_(sink), warnings_(warnings), uncompensated_(options.toolNoses) {}

void MovePipeline::add(const std::vector<Move>& moves, const std::optional<ContourPass>& pass, bool legsCompensated) {
  if (pass && !moves.empty()) uncompensated_.noteContourPass(moves.front().block, *pass);
  if (legsCompensated && !moves.empty()) uncompensated_.noteCompensatedBlock(moves.front().block);
  held_.insert(held_.end(), moves.begin(), moves.end());
}

bool MovePipeline::cutAfterLast() const {
  if (held_.empty()) return false;
  const Move& last = held_.back();
  return !last.cornerAfter && last.noseComp.side == NoseSide::None && last.kind != MoveKind::Dwell;
}

Status MovePipeline::release(bool anyCount) {
  if (!anyCount && held_.size() < options_.moveWindow) return success();
  if (!cutAfterLast()) return success();
  return pass();
}

Status MovePipeline::finish() {
  if (auto status = pass(); !status.ok()) return status;
  if (auto warning = uncompensated_.warning()) warnings_.push_back(std::move(*warning));
  return success();
}

// The moves are made as programmed, in the work coordinate systems (G54–G59, G50); placed in
// the setup's frame, then G41/G42 and the tool offsets' shifts are applied, each rapid is
// given the path the machine makes, and the whole checked against the machine's travel.
Status MovePipeline::pass() {
  std::vector<Move> moves = std::exchange(held_, {});
  if (auto status = insertCorners(moves, warnings_); !status.ok()) return status;
  placeInSetupFrame(moves);
  uncompensated_.look(moves);
  if (auto status = compensateNoseRadius(moves); !status.ok()) return status;
  if (auto status = applyToolOffsets(moves, shiftInForce_); !status.ok()) return status;
  if (options_.control.rapidPath == RapidPath::NonLinear) splitRapidsIntoAxisLegs(moves, options_.machine);
  if (passed_ + moves.size() > options_.maxMoves) {  // the dog-legs' second legs count too
    const Move& past = moves[options_.maxMoves - passed_];  // at the line of the move past the limit
    return *moveLimitError(passed_ + moves.size(), options_.maxMoves, past.line, past.column);
  }
  if (options_.machine.travel)
    if (auto status = checkTravel(moves, *options_.machine.travel, travelWarned_, warnings_); !status.ok()) return status;
  for (Move& move : moves) sink_.take(std::move(move));
  passed_ += moves.size();
  return success();
}

}  // namespace lathesim::interp
