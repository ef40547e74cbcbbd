#pragma once
// --animate: the run's cut recorded while it is simulated (render/cut_animation.hpp), each
// frame's part a mesh made for the picture from the stock's section.

#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/staged_output.hpp"
#include "setup/job.hpp"
#include "render/cut_animation.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

class CutRecording {
 public:
  /// Stages cut.mp4 (and cut.gif) in `out`; frames of part.png's view without its dimensions.
  CutRecording(const setup::Job& job, const AnimationRequest& request, const std::string& title, StagedOutput& out);

  /// What the simulation calls before each group of moves it cuts.
  sim::CutObserver observer();
  /// The last frames, with the stock as the program leaves it and every collision marked;
  /// closes the video.
  void finish(const sim::Stock& stock, const std::vector<sim::Collision>& collisions);
  /// Wall time spent on the frames and the video so far (s).
  double secondsSpent() const { return secondsSpent_; }

 private:
  /// The stock as it stands, meshed for the picture: its section revolved (a thread shows as rings).
  TriangleMesh partMesh(const sim::Stock& stock) const;
  /// Marks the collisions not marked yet, from the next frame on.
  void markCrashes(const std::vector<sim::Collision>& collisions);

  const setup::Job& job_;
  double toleranceMm_ = 0.1;  // how far the frame's mesh may stray from the section: about half a pixel
  int angularSteps_ = 12;
  std::size_t crashesMarked_ = 0;
  double secondsSpent_ = 0;
  std::unique_ptr<render::CutAnimation> animation_;
};

}  // namespace lathesim::app
