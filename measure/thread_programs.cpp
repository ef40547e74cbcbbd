#include "measure/thread_programs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "interp/control/gcode_table.hpp"

namespace lathesim::measure {
namespace {

using interp::Move;
using interp::MoveKind;

int signOf(double v) { return v < 0 ? -1 : 1; }

// What must agree for two passes to belong to one thread.
struct PassKey {
  int tool;
  double leadMm;
  bool leadAlongZ;
  int travelSign;
  int spindleSense;
  bool operator==(const PassKey&) const = default;
};

PassKey keyOf(const Move& first) {
  const double travel = first.thread.leadAlongZ ? first.to.y() - first.from.y() : first.to.x() - first.from.x();
  return {first.tool, first.thread.leadMm, first.thread.leadAlongZ, signOf(travel),
          first.spindleDirection == interp::SpindleDirection::Clockwise ? 1 : -1};
}

double spanLow(const Move& m, bool alongZ) { return alongZ ? std::min(m.from.y(), m.to.y()) : std::min(m.from.x(), m.to.x()); }
double spanHigh(const Move& m, bool alongZ) { return alongZ ? std::max(m.from.y(), m.to.y()) : std::max(m.from.x(), m.to.x()); }

}  // namespace

std::vector<ProgrammedThread> programmedThreads(const interp::Toolpath& toolpath,
                                                const std::map<int, ConvexPolygon>& tools, interp::Dialect dialect) {
  const auto& moves = toolpath.moves;
  std::vector<ProgrammedThread> threads;
  bool open = false;  // the last thread may take the next pass
  std::optional<PassKey> openKey;
  for (std::size_t m = 0; m < moves.size();) {
    const Move& move = moves[m];
    if (move.kind != MoveKind::Thread) {
      if (move.kind != MoveKind::Rapid && move.kind != MoveKind::Dwell) open = false;  // a cut ends the thread
      ++m;
      continue;
    }
    ThreadPass pass{m, m + 1};
    while (pass.endMove < moves.size() && moves[pass.endMove].kind == MoveKind::Thread &&
           moves[pass.endMove].from == moves[pass.endMove - 1].to)
      ++pass.endMove;
    m = pass.endMove;

    const Move& cut = moves[pass.firstMove];  // the pass's main cut (its run-out follows)
    const PassKey key = keyOf(cut);
    const bool alongZ = cut.thread.leadAlongZ;
    ProgrammedThread* thread = nullptr;
    if (open && openKey == key) {
      ProgrammedThread& last = threads.back();
      const double lo = spanLow(cut, alongZ), hi = spanHigh(cut, alongZ);
      const double lastLo = alongZ ? last.zMinMm : std::numeric_limits<double>::lowest();
      const double lastHi = alongZ ? last.zMaxMm : std::numeric_limits<double>::max();
      if (hi >= lastLo && lo <= lastHi) thread = &last;
    }
    if (!thread) {
      ProgrammedThread fresh;
      fresh.line = cut.line;
      fresh.column = cut.column;
      fresh.code = interp::writtenGCode(32, interp::GGroup::Motion, dialect);
      for (const auto& start : toolpath.cycleStarts)
        if (start.block == cut.block) fresh.code = start.code;
      fresh.tool = key.tool;
      fresh.leadMm = key.leadMm;
      fresh.leadAlongZ = key.leadAlongZ;
      fresh.travelSign = key.travelSign;
      fresh.spindleSense = key.spindleSense;
      // Right hand: the groove advances toward +Z as the part's azimuth grows, i.e. the travel
      // along Z and the spindle's turning have opposite signs (helical_sweep.hpp).
      fresh.rightHand = key.travelSign * key.spindleSense < 0;
      const auto tool = tools.find(key.tool);
      fresh.internal = tool != tools.end() && tool->second.upperBound().x() <= 1e-9 && tool->second.lowerBound().x() < 0;
      fresh.rootRadiusMm = cut.from.x();
      fresh.zMinMm = std::min(cut.from.y(), cut.to.y());
      fresh.zMaxMm = std::max(cut.from.y(), cut.to.y());
      threads.push_back(fresh);
      thread = &threads.back();
    }
    thread->passes.push_back(pass);
    const double deepest = thread->internal ? std::max(thread->rootRadiusMm, cut.from.x()) : std::min(thread->rootRadiusMm, cut.from.x());
    thread->rootRadiusMm = deepest;
    thread->zMinMm = std::min({thread->zMinMm, cut.from.y(), cut.to.y()});
    thread->zMaxMm = std::max({thread->zMaxMm, cut.from.y(), cut.to.y()});
    open = true;
    openKey = key;
  }

  // Starts: as programmed (G92 L, HNC C), or for G32 the distinct start angles of its passes;
  // a G76 thread has one.
  for (ProgrammedThread& thread : threads) {
    std::set<long> angles;
    int programmed = 1;
    for (const ThreadPass& pass : thread.passes) {
      const interp::ThreadMotion& motion = moves[pass.firstMove].thread;
      programmed = std::max(programmed, motion.starts);
      angles.insert(std::lround(motion.startAngleDeg * 100.0) % 36000);
    }
    thread.starts = std::max(programmed, static_cast<int>(angles.size()));
    const double period = 360.0 / thread.starts;
    double angle = std::fmod(moves[thread.passes.back().firstMove].thread.startAngleDeg, period);
    thread.startAngleDeg = angle > period / 2 ? angle - period : angle;
  }
  return threads;
}

}  // namespace lathesim::measure
