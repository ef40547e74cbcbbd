#pragma once
// Progress of a long run on a terminal ("blocks 12/40, 3.1 s"); silent when stderr is not a
// terminal, and silent for the first second so quick runs print nothing.

#include <chrono>
#include <string>

namespace lathesim::app {

class Progress {
 public:
  explicit Progress(std::string what);
  ~Progress();  // ends the line if anything was shown
  void update(int done, int total);

 private:
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastShown_;
  bool enabled_;
  bool shown_ = false;
};

}  // namespace lathesim::app
