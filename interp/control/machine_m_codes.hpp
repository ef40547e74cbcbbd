#pragma once
// The machine's own M codes: functions that change nothing the simulation sees (chuck,
// tailstock, chip conveyor, door, air blast, gear range, counters …). Each control family
// numbers them its own way, so the list is the control's (parameter m_codes): a code on it is
// accepted and listed once as ignored; a code on no list and not in the common table
// (gcode_table.cpp) is an error naming what this control takes. Codes that do change the
// simulation (spindle, coolant-free program flow, part catcher) are in the common table.

#include <span>
#include <string>
#include <string_view>

namespace lathesim::interp {

/// Whose machine M codes a control accepts as ignored (control parameter m_codes).
enum class MachineMCodes { Gsk980tdi, Fanuc0iT, Haas };

struct MachineMCode {
  int number = 0;
  std::string_view meaning;
};

/// The machine M codes of `family`, by number.
std::span<const MachineMCode> machineMCodes(MachineMCodes family);

/// The entry for M`number` in `family`'s list, or nullptr.
const MachineMCode* findMachineMCode(int number, MachineMCodes family);

/// "M10 M11 …", for error messages.
std::string machineMCodeList(MachineMCodes family);

}  // namespace lathesim::interp
