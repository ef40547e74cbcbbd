#pragma once
// Progress of a long run on a terminal ("simulating part.nc: blocks 12/40, 3.1 s", then
// "meshing, 5.0 s" …); silent when stderr is not a terminal, and silent for the first
// second so quick runs print nothing.

#include <chrono>
#include <string>

namespace lathesim::app {

class Progress {
 public:
  explicit Progress(std::string what);
  ~Progress();  // calls finish()
  void finish();  // ends the line if anything was shown
  void update(int done, int total);
  void stage(const std::string& name);  // a step with no count, e.g. "meshing"

 private:
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastShown_;
  bool enabled_;
  bool shown_ = false;
  void show(const std::string& state, bool force);
};

}  // namespace lathesim::app
