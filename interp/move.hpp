#pragma once
// The interpreter's output: primitive moves in part coordinates, each traceable to its
// source. Every cycle is expanded into these, so sim and render never see G-code.

#include <string>
#include <vector>

#include "geometry/rz.hpp"

namespace lathesim::interp {

enum class MoveKind { Rapid, Feed };
enum class FeedMode { PerMinute, PerRevolution };  // G98 / G99 (system A)

struct Move {
  MoveKind kind = MoveKind::Rapid;
  RZ from{0, 0};  // (radius mm, Z mm) — halved from the programmed diameter
  RZ to{0, 0};
  double feed = 0.0;  // in feedMode's unit (mm/min or mm/rev), converted to mm; 0 for rapids
  FeedMode feedMode = FeedMode::PerRevolution;
  int tool = 0;        // the tool number mounted (T0101 → 1)
  int toolOffset = 0;  // the offset number in force (T0101 → 1)
  bool spindleOn = false;
  int block = 0;      // 0-based ordinal of the source block: several blocks may share a line
  int line = 0;       // 1-based source line of that block
  int column = 0;     // 1-based column where that block starts
  int cycleStep = 0;  // 1–4 inside a G90/G94 cycle (rapid in, cut, retract, rapid back); 0 outside
};

struct Toolpath {
  std::string programName;  // the file name as given
  RZ startPosition{0, 0};   // where the tool stood before the first move
  std::vector<Move> moves;
  int blockCount = 0;       // blocks read, including those that made no move
};

inline const char* kindName(MoveKind kind) { return kind == MoveKind::Rapid ? "rapid" : "feed"; }

}  // namespace lathesim::interp
