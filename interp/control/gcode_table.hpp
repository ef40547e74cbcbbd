#pragma once
// What each G and M code means. The meanings are those of Fanuc/GSK system A; every
// dialect is a table from the codes it writes to those meanings (interp/control/dialect.hpp), so a
// Code carries the system-A number the executor acts on and the text the program wrote.

#include <string>
#include <string_view>

#include "interp/control/dialect.hpp"

namespace lathesim::interp {

/// Modal groups. A block may hold at most one code of each.
enum class GGroup {
  NonModal,     // 00: one-shot codes (G04 G10 G28 G50 G65 G70–G76)
  Motion,       // 01: G00 G01 G02 G03 G32 G90 G92 G94 — the cycles are modal motions
  Plane,        // 16: G17 G18 G19
  Units,        // 06: G20 G21
  NoseRadius,   // 07: G40 G41 G42
  SpindleMode,  // 02: G96 G97
  FeedMode,     // 05: G98 (mm/min) G99 (mm/rev)
  Distance,     // 03: absolute / incremental (system B and HNC write G90 / G91; system A
                //     has no such codes: X/Z are absolute, U/W incremental)
  WorkCoordinates,  // 14: G54–G59, the work coordinate systems (work offsets)
  DrillingCycle,    // 10: G80 (cancel), G81–G83 drilling and G84 tapping on the axis (Fanuc T: G83–G89)
};

/// The numbers of the Distance group's meanings (they have no system-A code).
inline constexpr int kAbsoluteDistance = 90;
inline constexpr int kIncrementalDistance = 91;

enum class MGroup {
  ProgramEnd,  // M02 M30
  Spindle,     // M03 M04 M05
  Coolant,     // M08 M09
  Stop,        // M00 M01
  Subprogram,  // M98 M99
  PartsCatcher,  // Haas M35 M36 M37: moves nothing the tool cuts; reported at a part-off
  ToolChange,    // M06: the trainers' (Denford, Boxford, Emco) tool change; the block's T names the tool
};

struct GCodeInfo {
  int number = 0;  // the system-A code with this meaning (Distance group: see above)
  GGroup group = GGroup::NonModal;
  bool supported = false;  // false: a real code lathesim does not simulate yet
  std::string_view meaning;
  std::string_view lacks = {};  // not empty: what the code needs that this two-axis lathe does
                                // not have (live tooling, a C axis …); it is refused saying so
};

struct MCodeInfo {
  int number = 0;
  MGroup group = MGroup::ProgramEnd;
  bool supported = false;
  std::string_view meaning;
  std::string_view lacks = {};  // as for GCodeInfo
};

/// What G`written` means in `dialect`, or nullptr when the dialect has no such code.
const GCodeInfo* findGCode(int written, Dialect dialect = Dialect::FanucA);

/// How `dialect` writes the system-A code `number` of `group`, e.g. G77 for G90 in fanuc-b.
std::string writtenGCode(int number, GGroup group, Dialect dialect);

/// The word that gives a single cycle's taper: R on Fanuc and GSK, I (axial: G80, G82) or K
/// (face: G81) on HNC. `cycle` is the system-A code, 90, 92 or 94.
char cycleTaperLetter(int cycle, Dialect dialect);

/// The codes `dialect` reads, for error messages: "G00 G01 …".
std::string supportedGCodes(Dialect dialect);
std::string supportedMCodes();

/// The entry for M`number`, or nullptr when no such code is known.
const MCodeInfo* findMCode(int number);

/// A name for error messages, e.g. "motion (group 01)".
std::string_view groupName(GGroup group);
std::string_view groupName(MGroup group);

}  // namespace lathesim::interp
