#pragma once
// What a nose radius does to a contour cut under G40 (lathe-cycles.md §8). Without
// compensation the imaginary tip P runs on the drawn path, and the nose circle, of radius R
// about C = P − R·s (s the tip number's direction, geometry/imaginary_tip.hpp), is where the
// tool really is. Its envelope misses the drawn surface except where the tip touches off: on
// the diameters and faces of tips 1–8 the nose touches at P; on a line at another angle, with
// unit normal n, the centre path runs R·|s·n| from the drawn line and the nose stops
// R·(|s·n| − 1) short of it (material left when > 0, cut into the part when < 0): for tip 3
// on a 45° chamfer |s·n| = √2, so R(√2 − 1) = 0.331 mm at R0.8. On an arc about O of radius ρ
// the centre path is the arc moved by −R·s, and the drawn point Q lies |‖Q − O + R·s‖ − ρ| − R
// from the cut (the same R(√2 − 1) where the arc's normal is along s). The side the tool is on
// is not stated under G40: a surface whose normal is square to s (a face for a tip 5 tool)
// tells nothing and is left out, as the tip then touches only by its own corner; tip 0/9
// (P = C) is R off everywhere.
// G71–G73 only rough a contour: their passes along it (the last one above all) make the surface
// only when no G70 finishes that contour after them, so they are weighed apart, by contour.

#include <cstddef>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "interp/base/move.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// A tool's insert as the setup draws it: its nose radius and imaginary tip number.
struct ToolNose {
  double radiusMm = 0;
  int tip = 0;
};

/// The worst deviation of one move from its drawn path, normal to the surface.
struct NoseDeviation {
  double mm = 0;  // > 0: material left standing; < 0: the nose cuts into the part
};

/// The deviation of a straight feed or arc `move` cut with nose radius `radiusMm` and tip
/// `tip` with no compensation; none for other moves or where no side can be told.
std::optional<NoseDeviation> uncompensatedDeviation(const Move& move, double radiusMm, int tip);

/// A compound cycle's pass over its contour, the P–Q blocks by their indices in the program:
/// G71–G73 rough it, G70 finishes it.
struct ContourPass {
  std::size_t first = 0, last = 0;
  bool finishes = false;
  bool compensated = false;  // a roughing against a contour its blocks' G41/G42 offset
};

/// The worst deviation over a run's moves, told once, as one warning at the block that has it:
/// the same error repeats on every contour a program cuts this way.
class UncompensatedNoseCheck {
 public:
  /// The nose of a move is its offset's R and tip (what G41/G42 would use), or where the
  /// offset gives no R, its tool's insert from `toolNoses`.
  explicit UncompensatedNoseCheck(const std::map<int, ToolNose>& toolNoses) : toolNoses_(toolNoses) {}
  /// Block `block` (its ordinal) ran `pass`; told in program order, before its moves are looked at.
  void noteContourPass(int block, const ContourPass& pass);
  /// Block `block` (its ordinal) is a G90/G94 whose legs its cycle offset for the nose
  /// (cycle_nose_compensation.hpp): they are cut compensated, whatever their NoseComp says.
  void noteCompensatedBlock(int block) { compensatedBlocks_.insert(block); }
  /// Looks at `moves` as programmed, before compensation: those under G40.
  void look(const std::vector<Move>& moves);
  /// The warning, if the worst deviation is 0.001 mm or more, of the moves that made the part's
  /// surface: the roughing of a contour a G70 finished after it is left out.
  std::optional<Error> warning() const;

 private:
  struct Worst {
    std::optional<NoseDeviation> deviation;
    Move at;                // the move that has it
    ToolNose nose;          // and the nose it was cut with
    bool ofOffset = true;   // that nose is its offset's, else its tool's insert
    bool exceeds(const Worst& other) const {
      return deviation && (!other.deviation || std::abs(deviation->mm) > std::abs(other.deviation->mm));
    }
  };
  using ContourKey = std::pair<std::size_t, std::size_t>;  // its first and last block

  const std::map<int, ToolNose>& toolNoses_;
  Worst worst_;                             // of the moves that are no roughing
  std::map<ContourKey, Worst> roughing_;    // of the roughing passes, by contour
  std::map<int, ContourKey> roughedBy_;     // the G71–G73 blocks (ordinals) and their contours
  std::set<int> compensatedBlocks_;  // roughings whose legs follow a compensated contour, cycles that offset theirs
  std::map<ContourKey, std::size_t> roughedAt_, finishedAt_;  // the last pass of each kind, in order
  std::size_t passes_ = 0;
};

}  // namespace lathesim::interp
