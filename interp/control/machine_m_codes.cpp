// The lists (README "The control" marks them ⚠: no manual's M-code table was at hand to
// check them number by number; they follow each family's usual assignments).
#include "interp/control/machine_m_codes.hpp"

#include <array>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

// GSK980TDi: chuck and tailstock, lubrication, the spindle's gear ranges. M13 (chuck release on
// the GSK) is left out: Doosan and Fanuc programs write it to start a live tool, which this
// lathe refuses by name (gcode_table.cpp) rather than skip.
constexpr std::array kGsk{
    MachineMCode{10, "tailstock forward"},  MachineMCode{11, "tailstock back"},
    MachineMCode{12, "chuck clamp"},        MachineMCode{32, "lubrication on"},
    MachineMCode{33, "lubrication off"},    MachineMCode{41, "spindle gear range 1"},
    MachineMCode{42, "spindle gear range 2"}, MachineMCode{43, "spindle gear range 3"},
    MachineMCode{44, "spindle gear range 4"},
};

// Fanuc 0i-T lathes: M codes above the standard ones are the machine builder's; these are the
// common ones (chuck, tailstock, chip conveyor, parts counter, gear ranges).
constexpr std::array kFanuc{
    MachineMCode{10, "chuck clamp"},          MachineMCode{11, "chuck unclamp"},
    MachineMCode{21, "tailstock forward"},    MachineMCode{22, "tailstock back"},
    MachineMCode{26, "chip conveyor on"},     MachineMCode{27, "chip conveyor off"},
    MachineMCode{41, "spindle gear range 1"}, MachineMCode{42, "spindle gear range 2"},
    MachineMCode{43, "spindle gear range 3"}, MachineMCode{44, "spindle gear range 4"},
    MachineMCode{68, "chuck clamp"},          MachineMCode{69, "chuck unclamp"},
    MachineMCode{73, "parts counter"},
};

// Haas lathes (the Haas lathe M-code list). M12–M15 are Haas's own (air blast, spindle brake),
// not live-tool codes; Haas's live tool is M133–M135, refused by name.
constexpr std::array kHaas{
    MachineMCode{10, "chuck clamp"},           MachineMCode{11, "chuck unclamp"},
    MachineMCode{12, "auto air jet on"},       MachineMCode{13, "auto air jet off"},
    MachineMCode{14, "main spindle clamp"},    MachineMCode{15, "main spindle unclamp"},
    MachineMCode{21, "tailstock advance"},     MachineMCode{22, "tailstock retract"},
    MachineMCode{31, "chip auger forward"},    MachineMCode{33, "chip auger stop"},
    MachineMCode{38, "spindle speed variation on"}, MachineMCode{39, "spindle speed variation off"},
    MachineMCode{41, "spindle low gear"},      MachineMCode{42, "spindle high gear"},
    MachineMCode{51, "user relay on"},         MachineMCode{52, "user relay on"},
    MachineMCode{53, "user relay on"},         MachineMCode{54, "user relay on"},
    MachineMCode{55, "user relay on"},         MachineMCode{56, "user relay on"},
    MachineMCode{57, "user relay on"},         MachineMCode{58, "user relay on"},
    MachineMCode{59, "output relay set"},      MachineMCode{61, "user relay off"},
    MachineMCode{62, "user relay off"},        MachineMCode{63, "user relay off"},
    MachineMCode{64, "user relay off"},        MachineMCode{65, "user relay off"},
    MachineMCode{66, "user relay off"},        MachineMCode{67, "user relay off"},
    MachineMCode{68, "user relay off"},        MachineMCode{69, "output relay clear"},
    MachineMCode{85, "automatic door open"},   MachineMCode{86, "automatic door close"},
    MachineMCode{88, "high pressure coolant on"}, MachineMCode{89, "high pressure coolant off"},
};

}  // namespace

std::span<const MachineMCode> machineMCodes(MachineMCodes family) {
  switch (family) {
    case MachineMCodes::Gsk980tdi: return kGsk;
    case MachineMCodes::Fanuc0iT: return kFanuc;
    case MachineMCodes::Haas: return kHaas;
  }
  return {};
}

const MachineMCode* findMachineMCode(int number, MachineMCodes family) {
  for (const MachineMCode& code : machineMCodes(family))
    if (code.number == number) return &code;
  return nullptr;
}

std::string machineMCodeList(MachineMCodes family) {
  std::string list;
  for (const MachineMCode& code : machineMCodes(family))
    list += fmt::format("{}M{:02}", list.empty() ? "" : " ", code.number);
  return list;
}

}  // namespace lathesim::interp
