#pragma once
// The interpreter's output: primitive moves in the setup's frame (the frame of the stock and
// the start point), each traceable to its source. Every cycle is expanded into these, so sim and render never see G-code.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rz.hpp"

namespace lathesim::interp {

// Rapid and Feed are straight. ArcCW / ArcCCW are G02 / G03: clockwise / counter-clockwise
// in the usual drawing view (Z to the right, X up, the upper half of the part), about
// `center`. A Dwell stands still for `dwellS` (from == to). A Thread move is straight and
// synchronised with the spindle (G32, and the cut and run-out of G92 and G76): `thread`
// says how; its `feed` is the lead.
enum class MoveKind { Rapid, Feed, ArcCW, ArcCCW, Dwell, Thread };
enum class FeedMode { PerMinute, PerRevolution };  // G98 / G99 (system A)
enum class SpindleMode { Rpm, SurfaceSpeed };      // G97 / G96
enum class NoseSide { None, Left, Right };         // G40 / G41 / G42
enum class SpindleDirection { Clockwise, CounterClockwise };  // M03 / M04

/// How a Thread move is tied to the spindle. The spindle angle θ is measured from its
/// one-revolution signal in the direction it turns (M03 or M04): the move starts when the
/// spindle stands at `startAngleDeg` (G32/G92 Q, a start of G92 L; a move chained to the
/// thread move before it starts where that one ended), and each revolution carries the tool
/// `leadMm` along the lead axis (the long axis of the cut: Z, or X counted as a radius).
/// So the move takes |Δ along the lead axis| / leadMm revolutions.
struct ThreadMotion {
  double leadMm = 0;
  bool leadAlongZ = true;
  double startAngleDeg = 0;  // in [0, 360)
  int starts = 1;            // starts of the thread it cuts, as programmed (G92 L, HNC C)
  bool operator==(const ThreadMotion&) const = default;

  /// Revolutions the spindle makes while the tool goes from `from` to `to`.
  double revolutions(const RZ& from, const RZ& to) const {
    const double travel = leadAlongZ ? to.y() - from.y() : to.x() - from.x();
    return (travel < 0 ? -travel : travel) / leadMm;
  }
};

/// The nose radius compensation a move was programmed under (interp/compensation/nose_compensation.hpp):
/// the side, and the nose radius R and imaginary tip number (0–9) of the tool offset in force.
struct NoseComp {
  NoseSide side = NoseSide::None;
  double radiusMm = 0;
  int tip = 0;
  bool operator==(const NoseComp&) const = default;
};

/// A chamfer or corner radius a move asks for at its end, before the next move (GSK L / D,
/// Fanuc ,C / ,R; interp/motion/corners.hpp inserts it).
struct CornerRequest {
  bool round = false;          // a corner radius; else a chamfer
  double sizeMm = 0;           // the radius, or the chamfer's size
  bool chamferLength = false;  // the chamfer's own length (GSK L, No.181#0 = 0), else from the corner
  std::string word;            // as written, for messages
  int column = 0;
};

struct Move {
  MoveKind kind = MoveKind::Rapid;
  RZ from{0, 0};  // (radius mm, Z mm) — halved from the programmed diameter
  RZ to{0, 0};
  RZ center{0, 0};    // arcs only: the centre (radius mm, Z mm)
  double dwellS = 0;  // Dwell only: seconds
  double feed = 0.0;  // in feedMode's unit (mm/min or mm/rev), converted to mm; 0 for rapids
  FeedMode feedMode = FeedMode::PerRevolution;
  int tool = 0;        // the tool number mounted (T0101 → 1)
  int toolOffset = 0;  // the offset number in force (T0101 → 1)
  RZ offsetShift{0, 0};  // where that offset moves the tip from the programmed point (radius, Z)
  RZ workShift{0, 0};    // where program zero lies in the setup's frame (G54–G59, G10 L2, G50):
                         // the program's own coordinates are the move's minus this
  NoseComp noseComp;   // G41/G42 in force as programmed; the toolpath's moves are already
                       // compensated (from/to/center are the imaginary tip's path)
  bool spindleOn = false;
  // The text its block is in (Toolpath::sources; 0: the program's own): `line` and `column`
  // are in that text. 16 bits, in what was padding after spindleOn: a Move stays 272 B.
  std::uint16_t source = 0;
  SpindleDirection spindleDirection = SpindleDirection::Clockwise;  // the last M03/M04
  SpindleMode spindleMode = SpindleMode::Rpm;
  double spindleS = 0;                    // S in force: rpm (G97) or m/min (G96)
  std::optional<double> spindleLimitRpm;  // G50 S, in force under G96
  // A chamfer or corner radius to the next move: held apart (16 B in every move, not the 72 of
  // the request) since few moves ask for one, and none once interp/motion/corners.hpp has
  // inserted it, as every move leaving the interpreter is.
  std::shared_ptr<const CornerRequest> cornerAfter;
  double timeS = 0;   // how long the move takes on the machine (see interp/motion/cycle_time.hpp)
  int block = 0;      // 0-based ordinal of the source block: several blocks may share a line
  int line = 0;       // 1-based line of that block in its text (`source`)
  int column = 0;     // 1-based column where that block starts
  int cycleStep = 0;  // 1–4 inside a G90/G94 cycle (rapid in, cut, retract, rapid back), 1–2 in
                      // G28 (to the intermediate point, to the reference); 0 outside
  ThreadMotion thread{};  // Thread moves only
  double spindleAngleDeg = 0;  // where the spindle stands when the move starts: its angle from
                               // the one-revolution signal about +Z (M03 turns it up, M04
                               // down), in [0, 360); see interp/motion/spindle_angle.hpp
};

/// Where a canned cycle (G90, G94, …) started: its point A, where the tool stands when the
/// block is read. sim checks that it lies outside the stock as it is at that moment.
struct CycleStart {
  int block = 0;  // 0-based ordinal of the cycle's block
  int line = 0;
  int column = 0;
  RZ point{0, 0};    // (radius mm, Z mm)
  std::string code;  // "G90", "G94", …
  std::uint16_t source = 0;  // the text the block is in, as Move::source
};

/// Where the program reached M00 (program stop) or M01 (optional stop): the machine waits for
/// the operator there, so a stop is listed, not timed.
struct ProgramStop {
  int line = 0;
  int column = 0;    // of the M code
  std::string code;  // "M00" or "M01"
};

/// A parts catcher command reached (Haas M35/M36: in place to catch, M37: withdrawn). It moves
/// nothing the tool cuts; a part-off reports the one in force (sim/simulate.hpp).
struct PartsCatcherCommand {
  std::size_t movesBefore = 0;  // the toolpath's moves before it (it acts before its block's moves)
  int line = 0;
  int column = 0;    // of the M code
  std::string code;  // "M36"
  bool inPlace = false;
};

/// A text other than the program's own that moves come from: a subprogram's file (M98 or G65
/// found it in --programs or beside the program), reached by a call. The same file reached
/// by calls from different lines is one source per calling line, so that each move names the
/// call that led to it.
struct MoveSource {
  std::string file;    // as found
  int caller = 0;      // the source of the calling block (Toolpath::sources; 0: the program's own)
  int callLine = 0;    // of the M98/G65 block in the caller's text; 0 when too many calls were
  int callColumn = 0;  // told apart to keep them (Toolpath::kMaxSources)
};

struct Toolpath {
  std::string programName;  // the file name as given
  RZ startPosition{0, 0};   // where the tool stood before the first move
  std::vector<Move> moves;
  int blockCount = 0;       // blocks read, including those that made no move
  std::vector<CycleStart> cycleStarts;  // every cycle block run, in program order
  std::vector<ProgramStop> stops;       // every M00/M01 reached, in program order
  std::vector<PartsCatcherCommand> partsCatcher;  // every parts catcher command reached, in order
  // The texts moves came from besides the program's own: Move::source n ≥ 1 is sources[n − 1].
  std::vector<MoveSource> sources;
  static constexpr std::size_t kMaxSources = 65535;  // Move::source's 16 bits

  /// The file of source `source`: programName for 0.
  const std::string& fileOf(int source) const {
    return source == 0 ? programName : sources[static_cast<std::size_t>(source - 1)].file;
  }
  /// The calls that led to source `source`, innermost first: "called from O2000.nc:3, from
  /// main.nc:14"; empty for the program's own text.
  std::string calledFrom(int source) const;
};

inline std::string Toolpath::calledFrom(int source) const {
  std::string calls;
  while (source != 0) {
    const MoveSource& called = sources[static_cast<std::size_t>(source - 1)];
    if (called.callLine == 0) break;
    calls += (calls.empty() ? "called from " : ", from ") + fileOf(called.caller) + ":" + std::to_string(called.callLine);
    source = called.caller;
  }
  return calls;
}

inline bool isArc(MoveKind kind) { return kind == MoveKind::ArcCW || kind == MoveKind::ArcCCW; }

/// Moves that cut: straight feeds, arcs and thread moves.
inline bool isCutting(MoveKind kind) { return kind == MoveKind::Feed || isArc(kind) || kind == MoveKind::Thread; }

/// The kind as toolpath.csv and reports name it.
inline const char* kindName(MoveKind kind) {
  switch (kind) {
    case MoveKind::Rapid: return "rapid";
    case MoveKind::Feed: return "feed";
    case MoveKind::ArcCW: return "cw";
    case MoveKind::ArcCCW: return "ccw";
    case MoveKind::Dwell: return "dwell";
    case MoveKind::Thread: return "thread";
  }
  return "unknown";
}

}  // namespace lathesim::interp
