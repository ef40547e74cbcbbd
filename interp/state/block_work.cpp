#include "interp/state/block_work.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "interp/compensation/tool_offset.hpp"
#include "interp/motion/feed_warnings.hpp"

namespace lathesim::interp {

Result<AxisWords> BlockWork::takeAxisWords(Coordinates meaning) {
  AxisWords axes{block.take('X'), block.take('U'), block.take('Z'), block.take('W')};
  if (state.incremental && meaning == Coordinates::Target) {
    // Under G91 an X word is a distance like U (and U stays one): both given is the
    // same two-words-for-one-axis mistake as X with U, and is caught below.
    if (axes.x && !axes.u) std::swap(axes.x, axes.u);
    if (axes.z && !axes.w) std::swap(axes.z, axes.w);
  }
  // X with U (Z with W): the GSK takes the absolute word (§3.2), other controls alarm. Under
  // G91 both are distances: always an error.
  const bool absoluteWins =
      options.control.absoluteWithIncremental == AbsoluteWithIncremental::AbsoluteWins && !state.incremental;
  for (auto [absolute, incremental, axis] : {std::tuple{&axes.x, &axes.u, 'X'}, std::tuple{&axes.z, &axes.w, 'Z'}}) {
    if (!*absolute || !*incremental) continue;
    if (!absoluteWins) {
      return errorAt(std::max((*absolute)->column, (*incremental)->column),
                     fmt::format("{} and {} both give the {} axis ({} absolute, {} incremental); give one of them",
                                 (*absolute)->text(), (*incremental)->text(), axis, axis, axis == 'X' ? 'U' : 'W'));
    }
    warnings.push_back({block.line, (*incremental)->column,
                        fmt::format("{} is ignored: {} in the same block gives the {} axis (the absolute word "
                                    "wins, GSK980TDi §3.2)",
                                    (*incremental)->text(), (*absolute)->text(), axis)});
    incremental->reset();
  }
  return axes;
}

RZ BlockWork::endPoint(const AxisWords& a) {
  RZ to = state.position;
  if (a.x) to.x() = length(*a.x) / 2.0;
  if (a.u) to.x() += length(*a.u) / 2.0;
  if (a.z) to.y() = length(*a.z);
  if (a.w) to.y() += length(*a.w);
  return to;
}

void BlockWork::emit(MoveKind kind, const RZ& from, const RZ& to, int cycleStep, const RZ& center,
                     const ThreadMotion& thread) {
  // An arc back to its start is a full circle, a dwell stands still: both are kept.
  if (from == to && !isArc(kind) && kind != MoveKind::Dwell) return;
  warnIfSurfaceSpeedUnclamped();
  if (isCutting(kind) && kind != MoveKind::Thread) warnIfFeedImplausible();  // a thread's F is its lead
  Move move;
  move.kind = kind;
  move.from = from;
  move.to = to;
  move.center = center;
  move.feed = isCutting(kind) ? *state.feed : 0.0;
  move.feedMode = state.feedMode;
  if (kind == MoveKind::Thread) {  // the lead, per revolution whatever G98/G99 says
    move.feed = thread.leadMm;
    move.feedMode = FeedMode::PerRevolution;
    move.thread = thread;
  }
  move.tool = state.tool;
  move.toolOffset = state.toolOffset;
  move.offsetShift = offsetShift(state.offset);
  move.workShift = state.frame.shift();
  move.noseComp = noseCompWith(state.noseSide, state.offset);
  move.spindleOn = state.spindleOn;
  move.spindleDirection = state.spindleDirection;
  move.spindleMode = state.spindleMode;
  const bool surfaceSpeed = state.spindleMode == SpindleMode::SurfaceSpeed;
  move.spindleS = surfaceSpeed ? state.surfaceSpeedMPerMin : state.spindleSpeed;
  if (surfaceSpeed) move.spindleLimitRpm = state.spindleLimitRpm;
  move.block = ordinal;
  move.line = block.line;
  move.column = block.column;
  move.cycleStep = cycleStep;
  moves.push_back(move);
}

// Where a cut first runs at a feed (or feed mode) other than the cut before it's.
void BlockWork::warnIfFeedImplausible() {
  const std::pair current{*state.feed, state.feedMode};
  if (state.checkedFeed == current) return;
  state.checkedFeed = current;
  if (auto problem = implausibleFeed(state.feedWord, current.first, current.second, state.inch))
    warnings.push_back({block.line, block.column, *problem});
}

// The first move after G96 tells whether G50 S was given in time to limit it.
void BlockWork::warnIfSurfaceSpeedUnclamped() {
  const auto g96 = state.surfaceSpeedAwaitingMove;
  if (!g96) return;
  state.surfaceSpeedAwaitingMove.reset();
  if (state.spindleLimitRpm) return;
  warnings.push_back({g96->first, g96->second,
                      fmt::format("G96 with no G50 S before its first move: the spindle speed is "
                                  "limited only by the machine's max_rpm ({:g} rpm); give G50 S "
                                  "(the rpm limit) before G96",
                                  options.machine.maxRpm)});
}

// A cycle's legs are never part of a G41/G42 chain (lathe-cycles.md §8): G71–G73 rough
// against a contour already offset, G90/G94 are offset by their tip number
// (cycle_nose_compensation.hpp), G74/G75 and the thread codes get none; an open chain ends
// at the first leg. A leg that follows a contour block is that block's line: the surface it
// cuts is blamed there.
void BlockWork::emitLegs(const std::vector<CycleLeg>& legs) {
  const std::size_t first = moves.size();
  for (const CycleLeg& leg : legs) {
    const std::size_t before = moves.size();
    emit(leg.kind, leg.from, leg.to, leg.step, leg.center, leg.thread);
    if (leg.line > 0 && moves.size() > before) moves.back().line = leg.line, moves.back().column = leg.column;
  }
  for (std::size_t i = first; i < moves.size(); ++i) moves[i].noseComp = {};
}

void BlockWork::noteCycleStart(const RZ& start, const std::string& name) {
  cycleStarts.push_back({ordinal, block.line, block.column, start + state.frame.shift(), name});
}

std::optional<std::string> planeProblem(Plane plane, std::string_view code, std::string_view what) {
  if (plane == Plane::ZX) return std::nullopt;
  return fmt::format("{} under {}: this machine has no Y axis, so {} needs the ZX plane; select it with G18", code,
                     plane == Plane::XY ? "G17" : "G19", what);
}

}  // namespace lathesim::interp
