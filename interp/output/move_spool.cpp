#include "interp/output/move_spool.hpp"

#include <cstdint>
#include <stdexcept>
#include <type_traits>

namespace lathesim::interp {
namespace {

// A Move's fields as plain bytes: its points as (radius, Z) pairs, its enums and flags as
// single bytes, the optional spindle limit as a flag and a value.
struct MoveRecord {
  double from[2], to[2], center[2], offsetShift[2], workShift[2];
  double dwellS, feed, noseRadiusMm, spindleS, spindleLimitRpm, timeS, leadMm, startAngleDeg, spindleAngleDeg;
  std::int32_t tool, toolOffset, noseTip, block, line, column, starts;
  std::int16_t cycleStep;
  std::uint16_t source;
  std::uint8_t kind, feedMode, noseSide, spindleOn, spindleDirection, spindleMode, hasSpindleLimit, leadAlongZ;
};
static_assert(std::is_trivially_copyable_v<MoveRecord>, "records are spooled as their bytes");
static_assert(sizeof(MoveRecord) == 192, "no padding between the fields");

void put(double (&pair)[2], const RZ& p) { pair[0] = p.x(), pair[1] = p.y(); }
RZ rz(const double (&pair)[2]) { return {pair[0], pair[1]}; }

MoveRecord recordOf(const Move& m) {
  MoveRecord r{};
  put(r.from, m.from), put(r.to, m.to), put(r.center, m.center), put(r.offsetShift, m.offsetShift), put(r.workShift, m.workShift);
  r.dwellS = m.dwellS, r.feed = m.feed, r.noseRadiusMm = m.noseComp.radiusMm, r.spindleS = m.spindleS;
  r.spindleLimitRpm = m.spindleLimitRpm.value_or(0.0), r.timeS = m.timeS, r.leadMm = m.thread.leadMm;
  r.startAngleDeg = m.thread.startAngleDeg, r.spindleAngleDeg = m.spindleAngleDeg;
  r.tool = m.tool, r.toolOffset = m.toolOffset, r.noseTip = m.noseComp.tip, r.block = m.block, r.line = m.line;
  r.column = m.column, r.cycleStep = static_cast<std::int16_t>(m.cycleStep), r.source = m.source, r.starts = m.thread.starts;
  r.kind = static_cast<std::uint8_t>(m.kind), r.feedMode = static_cast<std::uint8_t>(m.feedMode);
  r.noseSide = static_cast<std::uint8_t>(m.noseComp.side), r.spindleOn = m.spindleOn;
  r.spindleDirection = static_cast<std::uint8_t>(m.spindleDirection), r.spindleMode = static_cast<std::uint8_t>(m.spindleMode);
  r.hasSpindleLimit = m.spindleLimitRpm.has_value(), r.leadAlongZ = m.thread.leadAlongZ;
  return r;
}

Move moveOf(const MoveRecord& r) {
  Move m;
  m.kind = static_cast<MoveKind>(r.kind);
  m.from = rz(r.from), m.to = rz(r.to), m.center = rz(r.center), m.offsetShift = rz(r.offsetShift), m.workShift = rz(r.workShift);
  m.dwellS = r.dwellS, m.feed = r.feed, m.feedMode = static_cast<FeedMode>(r.feedMode);
  m.tool = r.tool, m.toolOffset = r.toolOffset;
  m.noseComp = {static_cast<NoseSide>(r.noseSide), r.noseRadiusMm, r.noseTip};
  m.spindleOn = r.spindleOn != 0, m.spindleDirection = static_cast<SpindleDirection>(r.spindleDirection);
  m.spindleMode = static_cast<SpindleMode>(r.spindleMode), m.spindleS = r.spindleS;
  if (r.hasSpindleLimit) m.spindleLimitRpm = r.spindleLimitRpm;
  m.timeS = r.timeS, m.block = r.block, m.line = r.line, m.column = r.column, m.cycleStep = r.cycleStep;
  m.source = r.source;
  m.thread = {r.leadMm, r.leadAlongZ != 0, r.startAngleDeg, r.starts};
  m.spindleAngleDeg = r.spindleAngleDeg;
  return m;
}

}  // namespace

void MoveSpool::take(Move move) {
  if (move.cornerAfter) throw std::logic_error("a move still asking for a corner reached the move spool");
  const MoveRecord record = recordOf(move);
  file_.append(&record, sizeof record);
  ++count_;
}

void MoveSpool::forEach(const std::function<void(const Move&)>& visit) const {
  Reader reader(*this);
  while (std::optional<Move> move = reader.next()) visit(*move);
}

std::optional<Move> MoveSpool::Reader::next() {
  MoveRecord record;
  const std::size_t got = file_.read(&record, sizeof record);
  if (got == 0) return std::nullopt;
  if (got != sizeof record) throw std::runtime_error("the moves' temporary file ends inside a move");
  return moveOf(record);
}

}  // namespace lathesim::interp
