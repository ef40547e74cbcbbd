#pragma once
// The cut as it happens: frames of a part picture taken at an even pace of machine time (or
// of tool travel) while the simulation runs, encoded by ffmpeg as they come.
//
// The simulation tells the animation before each group of moves it cuts (sim::CutObserver);
// every frame due before those moves end is drawn then, with the part as it stands before
// them and the tool where it is at the frame's moment. So a frame shows the stock block by
// block and the tool between.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "interp/motion/toolpath_clock.hpp"
#include "render/part_image.hpp"

namespace lathesim::render {

class PartPicture;
class VideoEncoder;

struct AnimationOptions {
  int frames = 120;  // at least 2: the first at the clock's start, the last at its end
  double framesPerSecond = 15;
  interp::Pace pace = interp::Pace::MachineTime;
  std::filesystem::path mp4;
  std::optional<std::filesystem::path> gif;  // made from the MP4 when given
  int gifWidthPx = 480;
};

/// What a frame says under the title, and which tool it shows, at an instant of the program.
using FrameCaption = std::function<std::string(const interp::ToolpathInstant& instant, double clock)>;
using FrameTool = std::function<std::optional<ToolPicture>(const interp::ToolpathInstant& instant)>;
/// The part as it stands now, as a mesh (asked only when a frame is due).
using PartNow = std::function<TriangleMesh()>;

class CutAnimation {
 public:
  /// Frames of `picture` (its size, view, bar and chuck; the toolpath drawn as far as each
  /// frame), `options.frames` of them at even steps from 0 to the clock's total.
  CutAnimation(const PartImageOptions& picture, const interp::Toolpath& toolpath, const AnimationOptions& options,
               FrameCaption caption, FrameTool tool);
  ~CutAnimation();
  CutAnimation(const CutAnimation&) = delete;
  CutAnimation& operator=(const CutAnimation&) = delete;

  /// The clock's step between frames (s, or mm for Pace::Travel).
  double stepPerFrame() const;
  /// The clock value of frame `index`.
  double clockOfFrame(int index) const;
  /// The clock when move `index` of the toolpath ends.
  double clockAtEndOf(std::size_t move) const { return clock_.endOf(move); }

  /// Draws every frame due before the clock reaches `clock`, the part as `part` gives it.
  void drawFramesBefore(double clock, const PartNow& part);
  /// Draws the frames left (the last at the end of the program) and ends the video; then the GIF.
  void finish(const PartNow& part);

  int framesDrawn() const { return next_; }
  /// Marks a crash in the frames drawn from now on.
  void addCrash(const CrashMark& crash);

 private:
  void draw(int index, const TriangleMesh& part);

  const interp::Toolpath& toolpath_;
  AnimationOptions options_;
  interp::ToolpathClock clock_;
  FrameCaption caption_;
  FrameTool tool_;
  std::unique_ptr<PartPicture> picture_;
  std::unique_ptr<VideoEncoder> encoder_;
  std::vector<unsigned char> rgb_;
  int next_ = 0;
};

}  // namespace lathesim::render
