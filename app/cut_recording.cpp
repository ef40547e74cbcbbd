#include "app/cut_recording.hpp"

#include <chrono>
#include <cstdio>
#include <string_view>

#include "app/collision_diagnostics.hpp"
#include "app/part_pictures.hpp"
#include "app/tool_picture.hpp"
#include "geometry/profile_polylines.hpp"
#include "geometry/revolved_mesh.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/text/text_lines.hpp"

namespace lathesim::app {
namespace {

std::string clockText(double clock, interp::Pace pace) {
  char text[32];
  if (pace == interp::Pace::Travel) std::snprintf(text, sizeof text, "%.0f mm", clock);
  else std::snprintf(text, sizeof text, "%d:%04.1f", static_cast<int>(clock / 60), clock - 60 * static_cast<int>(clock / 60));
  return text;
}

}  // namespace

CutRecording::CutRecording(const setup::Job& job, const AnimationRequest& request, const std::string& title,
                           StagedOutput& out)
    : job_(job) {
  render::PartImageOptions picture = partPictureOptions(job.setup, job.toolpath, title, request.widthPx, request.heightPx);
  // The run keeps every move for a video (run_pipeline.cpp): its tools and time are known now.
  picture.subtitle = pictureSubtitle(job.setup, toolsUsedBy(job.toolpath.moves), interp::cycleTimeS(job.toolpath));
  const sim::StockSpec& bar = job.setup.stock;
  // About half a pixel: the picture spans a little more than the bar and its jaws.
  toleranceMm_ = 0.5 * (bar.lengthMm + bar.diameterMm) / request.widthPx;
  angularSteps_ = angularStepsFor(bar.diameterMm / 2, toleranceMm_);

  render::AnimationOptions options;
  options.frames = request.frames;
  options.framesPerSecond = request.framesPerSecond;
  options.pace = request.pace;
  options.mp4 = out.stage("cut.mp4");
  if (request.gif) options.gif = out.stage("cut.gif");

  const auto lines = std::make_shared<std::vector<std::string>>(interp::linesOf(job.programText.text().view()));
  const double total = interp::ToolpathClock(job.toolpath, request.pace).total();
  const interp::Pace pace = request.pace;
  auto caption = [this, lines, total, pace](const interp::ToolpathInstant& instant, double clock) {
    const auto& moves = job_.toolpath.moves;
    std::string text = clockText(clock, pace) + " of " + clockText(total, pace);
    if (moves.empty()) return text;
    const int line = moves[std::min(instant.move, moves.size() - 1)].line;
    text += "   line " + std::to_string(line);
    if (line >= 1 && line <= static_cast<int>(lines->size())) text += ":  " + (*lines)[line - 1];
    return text;
  };
  auto tool = [this](const interp::ToolpathInstant& instant) -> std::optional<render::ToolPicture> {
    const auto& moves = job_.toolpath.moves;
    const int number = moves.empty() ? 0 : moves[std::min(instant.move, moves.size() - 1)].tool;
    return toolPicture(job_.setup, number, instant.position);
  };
  animation_ = std::make_unique<render::CutAnimation>(picture, job.toolpath, options, caption, tool);
}

TriangleMesh CutRecording::partMesh(const sim::Stock& stock) const {
  const MeridianProfile profile = MeridianProfile::fromSection(stock.meridianSection());
  return revolvedMesh(profilePolylines(profile, toleranceMm_), angularSteps_);
}

sim::CutObserver CutRecording::observer() {
  return [this](std::size_t, std::size_t endMove, const sim::Stock& stock, const std::vector<sim::Collision>& collisions) {
    const auto start = std::chrono::steady_clock::now();
    markCrashes(collisions);
    animation_->drawFramesBefore(animation_->clockAtEndOf(endMove - 1), [&] { return partMesh(stock); });
    secondsSpent_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
}

void CutRecording::markCrashes(const std::vector<sim::Collision>& collisions) {
  for (; crashesMarked_ < collisions.size(); ++crashesMarked_) animation_->addCrash(crashMarkOf(collisions[crashesMarked_]));
}

void CutRecording::finish(const sim::Stock& stock, const std::vector<sim::Collision>& collisions) {
  const auto start = std::chrono::steady_clock::now();
  markCrashes(collisions);
  animation_->finish([&] { return partMesh(stock); });
  secondsSpent_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lathesim::app
