#pragma once
// The machine's own M codes: functions outside the cutting the simulation models (chuck,
// tailstock, chip conveyor, door, air blast, gear range, counters, outputs …). Each control
// family numbers them its own way, so the table is the control's (parameter m_codes). A code
// in it is accepted, said once at the line that first names it:
//   - as a note when it moves nothing near the work (a conveyor, a door, a gear range);
//   - as a warning when it moves something lathesim does not simulate (a tailstock, a parts
//     catcher arm, a probe arm, the bar freed in the chuck): the program runs, but a collision
//     with that thing is not checked, and the warning says so. Never silently.
// A code in no table and not in the common table (gcode_table.cpp, whose live-tool and
// second-spindle codes are refused by name) is an error naming the tables looked in, and the
// families whose table does hold it. The tables are data: machineMCodes() lists every entry
// with its source, for the reference.

#include <span>
#include <string>
#include <string_view>

namespace lathesim::interp {

/// Whose machine M codes a control accepts (control parameter m_codes).
enum class MachineMCodes { Gsk980tdi, Fanuc0iT, Haas };

/// Every family, in the order the tables are searched and listed.
std::span<const MachineMCodes> machineMCodeFamilies();

/// The family's name as the m_codes parameter writes it: "gsk980tdi", "fanuc-0i-t", "haas".
std::string_view machineMCodeFamilyName(MachineMCodes family);

/// What a machine M code does that the simulation sees.
enum class MachineMotion {
  None,        // moves nothing near the work: a note
  Unsimulated  // moves something into or near the work that lathesim does not model: a warning
};

struct MachineMCode {
  int number = 0;
  std::string_view meaning;
  MachineMotion motion = MachineMotion::None;
  std::string_view source;  // the manual and section it is read from, or how it is known
};

/// The machine M codes of `family`, by number.
std::span<const MachineMCode> machineMCodes(MachineMCodes family);

/// The entry for M`number` in `family`'s list, or nullptr.
const MachineMCode* findMachineMCode(int number, MachineMCodes family);

/// "M10 M11 …", for error messages.
std::string machineMCodeList(MachineMCodes family);

/// What is said where `code` first appears, written as `written`: "M21 (tailstock advance) moves …".
std::string machineMCodeMessage(const MachineMCode& code, std::string_view written);

}  // namespace lathesim::interp
