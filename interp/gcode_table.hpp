#pragma once
// The dialect: what each G and M code means for Fanuc/GSK system A, as a table.
// Another dialect (system B/C, Huazhong) would be another table, not scattered ifs.

#include <string_view>

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
};

enum class MGroup {
  ProgramEnd,  // M02 M30
  Spindle,     // M03 M04 M05
  Coolant,     // M08 M09
  Stop,        // M00 M01
  Subprogram,  // M98 M99
};

struct GCodeInfo {
  int number = 0;
  GGroup group = GGroup::NonModal;
  bool supported = false;  // false: a real code lathesim does not simulate yet
  std::string_view meaning;
};

struct MCodeInfo {
  int number = 0;
  MGroup group = MGroup::ProgramEnd;
  bool supported = false;
  std::string_view meaning;
};

/// The entry for G`number`, or nullptr when system A has no such code.
const GCodeInfo* findGCode(int number);

/// The entry for M`number`, or nullptr when no such code is known.
const MCodeInfo* findMCode(int number);

/// A name for error messages, e.g. "motion (group 01)".
std::string_view groupName(GGroup group);
std::string_view groupName(MGroup group);

}  // namespace lathesim::interp
