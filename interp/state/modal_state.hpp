#pragma once
// What the control remembers between blocks. All lengths are mm; X positions are radii.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "geometry/rz.hpp"
#include "interp/compensation/tool_offset.hpp"
#include "interp/contour/compound_params.hpp"
#include "interp/state/length_writing.hpp"
#include "interp/state/work_frame.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

// group 01: G00 G01 G02 G03 G90 G94 G32 G92
enum class MotionMode { Rapid, Linear, ArcCW, ArcCCW, AxialCycle, FaceCycle, Thread, ThreadCycle };
enum class Plane { XY, ZX, YZ };                                  // G17, G18, G19

/// The end point and taper of the last G90 or G94 block, reused by a following block of the
/// same cycle that omits them. Cleared by any other group-01 code (G00, G01, and G94 after
/// G90 or G90 after G94) and by every one-shot (group 00) code except G04.
struct CycleRetained {
  std::optional<double> xDiameterMm;  // absolute end X (C), a diameter
  std::optional<double> zMm;          // absolute end Z (C)
  std::optional<double> rMm;          // taper: G90 radius at the cut's start minus at its end;
                                      // G94 Z at the cut's start minus Z at its end
};

/// The run-out words of the thread codes (GSK J and K, HNC R and E), as read: modal while
/// blocks of one thread code follow each other (interp/cycles/thread_block.hpp).
struct RunoutWords {
  std::optional<double> acrossMm;  // J (GSK) / E (HNC): along the short axis (X as a radius)
  std::optional<double> alongMm;   // K (GSK) / R (HNC): along the long axis
};

/// What G92 keeps besides G90's values: its run-out words and its starts (GSK L, HNC C
/// and P). Cleared with CycleRetained.
struct ThreadCycleRetained {
  RunoutWords runout;
  int starts = 1;
  double firstStartDeg = 0;
};

/// F0 (GSK §3.26: the feed becomes 0) is legal, but a cut at it never ends on a machine: the
/// error for `what` ("G01", "G90") cutting at F0, or nullopt when the feed in force is not 0.
inline std::optional<std::string> zeroFeedProblem(std::optional<double> feed, std::string_view what) {
  if (!feed || *feed != 0) return std::nullopt;
  return std::string(what) + " cuts at F0, a feed of 0: the machine would wait there forever; give F > 0";
}

struct ModalState {
  MotionMode motion = MotionMode::Rapid;
  int drillingCycle = 0;            // G81–G84 in force (0: none): a later block with X(U) or Z(W)
  double drillingRPlaneZ = 0;       // drills again, to the same R point and bottom, with the same
  double drillingBottomZ = 0;       // peck and dwell, until G80 or a group 01 code
  double drillingPeckMm = 0;
  double drillingDwellS = 0;
  Plane plane = Plane::ZX;
  bool inch = false;  // G20; every length is converted to mm as it is read
  bool incremental = false;  // G91 in dialects that have it: X and Z words are distances
  FeedMode feedMode = FeedMode::PerRevolution;
  std::optional<double> feed;  // mm/min (G98) or mm/rev (G99); unset until the first F
  std::string feedWord;        // that F as the program wrote it, for messages
  std::optional<std::pair<double, FeedMode>> checkedFeed;  // the feed the last cut was checked at
  SpindleMode spindleMode = SpindleMode::Rpm;  // G97 is the power-on state
  double spindleSpeed = 0.0;                   // rpm under G97 (S, or kept from G96)
  double surfaceSpeedMPerMin = 0.0;            // G96 S, remembered across G97 periods
  std::optional<double> spindleLimitRpm;       // G50 S
  std::optional<std::pair<int, int>> surfaceSpeedAwaitingMove;  // (line, column) of a G96
                                                                // that has made no move yet
  bool spindleOn = false;
  SpindleDirection spindleDirection = SpindleDirection::Clockwise;  // the last M03/M04
  bool coolantOn = false;
  int tool = 0;
  int toolOffset = 0;
  bool toolCalled = false;  // a tool is selected: the setup's mounted one, or a T word's; T0 and
                            // T00 deselect it
  bool cutWithoutToolSaid = false;  // the warning of a cut before any tool call is given once
  ToolOffset offset;  // the values of offset `toolOffset` as its T word found them: G10 changes
                      // the table, and a changed entry takes effect at the next T word
  std::shared_ptr<const ToolOffsets> offsetTable;  // the table as G10 left it; null: the setup's
  NoseSide noseSide = NoseSide::None;  // group 07: G40 / G41 / G42
  WorkFrame frame;        // G54–G59 and their offsets (G10 L2 changes them), and G50's shift
  RZ position{0.0, 0.0};  // where the tool is in the selected work coordinate system
                          // (radius mm, Z mm); the setup's frame is position + frame.shift()
  std::optional<std::pair<int, int>> drillCancelWithCycle;  // (line, column) of a G80 read while
                                                            // G90/G92/G94 stayed modal
  CycleRetained cycle;
  ThreadCycleRetained threadCycle;  // G92's own retained words
  // G32 (lathe-cycles.md §2): a G32 block right after another does not wait for the spindle's
  // one-revolution signal; it starts at the angle where the last one's cut ended. Set by a
  // G32 block that cuts, cleared by every other block.
  std::optional<double> threadChainAngleDeg;
  RunoutWords threadChainRunout;  // GSK J/K of G32: kept along a chain of G32 blocks
  CompoundCycleParams compound;  // G71–G75 first-block values
  LengthWriting lengthWriting;   // lengths read with and without a decimal point
  bool ended = false;  // M02/M30 read: nothing after it runs
};

}  // namespace lathesim::interp
