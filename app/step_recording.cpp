#include "app/step_recording.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "app/tool_picture.hpp"
#include "geometry/meridian_profile.hpp"
#include "geometry/profile_polylines.hpp"
#include "sim/stock.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::ordered_json;

long micrometres(double mm) { return std::lround(mm * 1000.0); }

Json flat(const std::vector<std::array<long, 2>>& points, std::size_t from, std::size_t to) {
  Json values = Json::array();
  for (std::size_t i = from; i < to; ++i) values.push_back(points[i][0]), values.push_back(points[i][1]);
  return values;
}

/// A polyline as its change from the most alike one of `before`: [index, head, tail, the points
/// between] keeps `head` points from that one's start and `tail` from its end; [-1, 0, 0, all]
/// when none shares its start or its end.
Json delta(const std::vector<std::array<long, 2>>& now, const std::vector<std::vector<std::array<long, 2>>>& before) {
  long best = -1;
  std::size_t bestHead = 0, bestTail = 0;
  for (std::size_t p = 0; p < before.size(); ++p) {
    const auto& old = before[p];
    const std::size_t limit = std::min(old.size(), now.size());
    std::size_t head = 0;
    while (head < limit && old[head] == now[head]) ++head;
    std::size_t tail = 0;
    while (tail < limit - head && old[old.size() - 1 - tail] == now[now.size() - 1 - tail]) ++tail;
    if (head + tail > bestHead + bestTail) best = static_cast<long>(p), bestHead = head, bestTail = tail;
  }
  return Json::array({best, bestHead, bestTail, flat(now, bestHead, now.size() - bestTail)});
}

/// The spindle's speed at the end of `move`: S under G97; under G96 the surface speed at that
/// diameter, held to the G50 limit.
double rpmAtEnd(const interp::Move& move) {
  if (move.spindleMode == interp::SpindleMode::Rpm) return move.spindleS;
  const double rpm = 1000.0 * move.spindleS / (std::numbers::pi * std::max(diameterOf(move.to), 1e-3));
  return move.spindleLimitRpm ? std::min(rpm, *move.spindleLimitRpm) : rpm;
}

Json polygon(const std::vector<RZ>& points) {
  Json values = Json::array();
  for (const RZ& p : points) values.push_back(micrometres(p.x())), values.push_back(micrometres(p.y()));
  return values;
}

double rounded(double value, double step) { return std::round(value / step) * step; }

}  // namespace

void StepRecording::take(interp::Move move) {
  const std::size_t index = moves_++;
  if (steps_.empty() || steps_.back().block != move.block) {
    if (!steps_.empty() && steps_.back().blocks < blocksPerStep_) {  // the step still has room
      Step& step = steps_.back();
      step.block = move.block, step.lastLine = move.line, ++step.blocks;
    } else {
      steps_.push_back({move.block, move.block, move.line, move.line, move.tool, 1, index, index});
      if (steps_.size() > kMaxSteps) mergeStepsInPairs();
    }
  }
  Step& step = steps_.back();
  step.endMove = index + 1;
  step.timeS += move.timeS;
  if (move.kind != interp::MoveKind::Rapid && move.kind != interp::MoveKind::Dwell) step.feed = move.feed;
  step.spindleS = move.spindleS;
  step.rpm = rpmAtEnd(move);
  step.tool = move.tool;
  step.end = {micrometres(move.to.x()), micrometres(move.to.y())};
  if (pathLeftOut_) return;
  if (moves_ > kMaxMoves) {  // json() says the toolpath is left out
    pathLeftOut_ = true;
    path_ = {};
    return;
  }
  path_.insert(path_.end(), {static_cast<long>(move.kind), step.end[0], step.end[1]});
  if (interp::isArc(move.kind)) path_.insert(path_.end(), {micrometres(move.center.x()), micrometres(move.center.y())});
}

// Each pair of neighbours as one step (an odd last one stays as it is, with room for more):
// from then on a step takes twice as many blocks. Sections stay; the page shows the last one
// taken at or before a step's end.
void StepRecording::mergeStepsInPairs() {
  std::vector<Step> merged;
  merged.reserve(kMaxSteps / 2 + 1);
  for (std::size_t s = 0; s < steps_.size(); s += 2) {
    Step step = steps_[s];
    if (s + 1 < steps_.size()) {
      const Step& second = steps_[s + 1];
      step.block = second.block, step.lastLine = second.lastLine, step.blocks += second.blocks;
      step.endMove = second.endMove;
      step.timeS += second.timeS;
      step.feed = second.feed, step.spindleS = second.spindleS, step.rpm = second.rpm;
      step.tool = second.tool, step.end = second.end;
    }
    merged.push_back(step);
  }
  steps_ = std::move(merged);
  blocksPerStep_ *= 2;
  nextStep_ /= 2;  // the step that holds the one it was at
}

void StepRecording::take(const sim::Stock& stock, std::size_t afterMove, bool always) {
  if ((!always && !sections_.empty() && afterMove < sections_.back().afterMove + everyMoves_)) return;
  const auto started = std::chrono::steady_clock::now();
  const double besides = std::chrono::duration<double>(started - started_).count() - secondsSpent_;
  if (!always && secondsSpent_ > kFreeSeconds && secondsSpent_ > kTimeShare * besides) return;  // over its share
  struct Spent {  // however take() returns
    double& seconds;
    std::chrono::steady_clock::time_point since;
    ~Spent() { seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count(); }
  } spent{secondsSpent_, started};
  Polylines polylines;
  for (const auto& line : profilePolylines(MeridianProfile::fromSection(stock.meridianSection()), toleranceMm_)) {
    auto& points = polylines.emplace_back();
    for (const RZ& p : line) points.push_back({micrometres(p.x()), micrometres(p.y())});
  }
  if (!sections_.empty() && sections_.back().polylines == polylines) return;
  sections_.push_back({afterMove, std::move(polylines)});
  if (sections_.size() > kMaxSections) {  // thin: keep the first, every other one after it, and the newest
    std::vector<Section> kept;
    for (std::size_t s = 0; s < sections_.size(); ++s)
      if (s % 2 == 0 || s + 1 == sections_.size()) kept.push_back(std::move(sections_[s]));
    sections_ = std::move(kept);
    everyMoves_ *= 2;
  }
}

sim::CutObserver StepRecording::observer() {
  return [this](std::size_t firstMove, std::size_t, const sim::Stock& stock, const std::vector<sim::Collision>&) {
    // Only between blocks: the page shows the stock after a block, never part way through one
    // (a G71 cuts in some forty groups).
    while (nextStep_ < steps_.size() && steps_[nextStep_].firstMove < firstMove) ++nextStep_;
    if (nextStep_ < steps_.size() && steps_[nextStep_].firstMove == firstMove) take(stock, firstMove, false);
  };
}

void StepRecording::finish(const sim::Stock& stock) { take(stock, moves_, true); }

Json StepRecording::json(const sim::BlockRows& rows, const setup::Setup& setup, const RZ& start) const {
  // The sections some step shows (the last taken at or before its end; a block of several
  // groups had one taken before each), the bar's first; each as its change from the one before.
  std::vector<std::size_t> shown{0};
  for (std::size_t s = 1, step = 0; s < sections_.size(); ++s) {
    while (step < steps_.size() && steps_[step].endMove < sections_[s].afterMove) ++step;
    const bool nextShownInstead = s + 1 < sections_.size() && step < steps_.size() &&
                                  sections_[s + 1].afterMove <= steps_[step].endMove;
    if (!nextShownInstead) shown.push_back(s);
  }
  Json sections = Json::array();
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const Section& section = sections_[shown[k]];
    Json polylines = Json::array();
    for (const auto& line : section.polylines)
      polylines.push_back(delta(line, k == 0 ? Polylines{} : sections_[shown[k - 1]].polylines));
    sections.push_back(Json::array({section.afterMove, polylines}));
  }
  // The rows are one a block run with moves, in the same order as the blocks the steps cover.
  std::vector<double> removed(steps_.size(), 0.0);
  std::size_t next = 0, taken = 0;  // the step being filled, and how many of its blocks' rows it has
  rows.forEach([&](const sim::BlockRemoval& row) {
    while (next < steps_.size() && (taken == steps_[next].blocks || (taken == 0 && steps_[next].firstBlock != row.block)))
      ++next, taken = 0;
    if (next < steps_.size()) removed[next] += row.removedMm3, ++taken;
  });
  Json steps = Json::array(), tools = Json::object();
  for (std::size_t s = 0; s < steps_.size(); ++s) {
    const Step& step = steps_[s];
    // The volume to 1e-6 mm³, so that the steps add up to the run's total.
    steps.push_back(Json::array({step.line, step.firstMove, step.endMove, std::round(removed[s] * 1e6) / 1e6,
                                 rounded(step.timeS, 0.01), step.end[0], step.end[1], rounded(step.feed, 0.0001),
                                 step.spindleS, std::round(step.rpm), step.tool, step.lastLine, step.blocks}));
    const std::string tool = std::to_string(step.tool);
    if (tools.contains(tool)) continue;
    const render::ToolPicture picture = toolPicture(setup, step.tool, RZ{0, 0});
    tools[tool] = {{"insert", polygon(picture.insert)}, {"holder", polygon(picture.holder)}};
  }
  return {{"every_moves", everyMoves_},
          {"blocks_per_step", blocksPerStep_},
          {"path_left_out", pathLeftOut_},
          {"start", {micrometres(start.x()), micrometres(start.y())}},
          {"sections", sections},
          {"steps", steps},
          {"path", path_},
          {"tools", tools}};
}

}  // namespace lathesim::app
