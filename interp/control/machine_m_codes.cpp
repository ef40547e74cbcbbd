// The tables. Sources: for Haas, the public Autodesk HAAS lathe post processor (haas lathe.cps,
// its getCode() table, which writes the codes a Haas lathe reads for each function), and for
// the codes it does not write the Haas lathe operator's manual's M-code list as recalled,
// marked unchecked; the GSK980TDi user manual's M-code table; the Fanuc builders' codes are
// each builder's (Doosan, Mori Seiki, Romi …), no Fanuc manual fixes them: Doosan's are read
// from the Autodesk DN Solutions (Doosan) post, the others are the common assignments and
// marked so. A code whose meaning differs between builders of one
// family is left out of it: an unknown code is an error, which is better than a guess that
// hides a move.
#include "interp/control/machine_m_codes.hpp"

#include <array>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

using enum MachineMotion;

constexpr std::string_view kGskManual = "GSK980TDi user manual, its M-code table (the list unchecked number by number)";

// GSK980TDi: tailstock, chuck, lubrication, the spindle's gear ranges. M13 (chuck release on
// the GSK) is left out: Doosan and Fanuc programs write it to start a live tool, which this
// lathe refuses by name (gcode_table.cpp) rather than skip.
constexpr std::array kGsk{
    MachineMCode{10, "tailstock forward", Unsimulated, kGskManual},
    MachineMCode{11, "tailstock back", Unsimulated, kGskManual},
    MachineMCode{12, "chuck clamp", None, kGskManual},
    MachineMCode{32, "lubrication on", None, kGskManual},
    MachineMCode{33, "lubrication off", None, kGskManual},
    MachineMCode{41, "spindle gear range 1", None, kGskManual},
    MachineMCode{42, "spindle gear range 2", None, kGskManual},
    MachineMCode{43, "spindle gear range 3", None, kGskManual},
    MachineMCode{44, "spindle gear range 4", None, kGskManual},
};

constexpr std::string_view kBuilder = "machine builder's code, the common assignment (Doosan/Mori Seiki/Romi "
                                      "manuals differ; unchecked)";
constexpr std::string_view kDoosanPost =
    "Autodesk DN Solutions (Doosan) lathe post processor for Fanuc 0i/31i (Puma, Lynx; getCode()), which "
    "writes it for this function";
constexpr std::string_view kDoosanPostBuildersDiffer =
    "Autodesk DN Solutions (Doosan) lathe post processor for Fanuc 0i/31i (getCode(): the parts catcher); "
    "other builders' chuck code (unchecked)";

// Fanuc 0i-T lathes: M codes above the standard ones are the machine builder's. Doosan's are
// read from the post that writes them; the others are the common ones, unchecked. Where the
// builders differ (M10/M11: Doosan's parts catcher, others' chuck) the entry names both, and
// is a warning: either reading moves something near the work that is not simulated. Doosan's
// air blast M14/M15 is left out: other Fanuc lathes start a live tool with M13–M15, which the
// common table refuses by name (gcode_table.cpp) rather than skip.
constexpr std::array kFanuc{
    MachineMCode{10, "chuck clamp, or on a Doosan the parts catcher forward", Unsimulated, kDoosanPostBuildersDiffer},
    MachineMCode{11, "chuck unclamp (the bar free in the chuck), or on a Doosan the parts catcher back", Unsimulated,
                 kDoosanPostBuildersDiffer},
    MachineMCode{21, "tailstock forward", Unsimulated, kBuilder},
    MachineMCode{22, "tailstock back", Unsimulated, kBuilder},
    MachineMCode{26, "chip conveyor on", None, kBuilder},
    MachineMCode{27, "chip conveyor off", None, kBuilder},
    MachineMCode{41, "spindle gear range 1", None, kBuilder},
    MachineMCode{42, "spindle gear range 2", None, kBuilder},
    MachineMCode{43, "spindle gear range 3", None, kBuilder},
    MachineMCode{44, "spindle gear range 4", None, kBuilder},
    MachineMCode{68, "chuck clamp", None, kDoosanPost},
    MachineMCode{69, "chuck unclamp: the bar is free in the chuck", Unsimulated, kDoosanPost},
    MachineMCode{73, "parts counter", None, kBuilder},
    MachineMCode{78, "tailstock forward (Doosan)", Unsimulated, kDoosanPost},
    MachineMCode{79, "tailstock back (Doosan)", Unsimulated, kDoosanPost},
    MachineMCode{110, "turret interference check off (Doosan)", None, kDoosanPost},
    MachineMCode{111, "turret interference check on (Doosan)", None, kDoosanPost},
    MachineMCode{116, "part ejector cycle (Doosan): pushes the part out", Unsimulated, kDoosanPost},
};

constexpr std::string_view kHaasManual =
    "Haas lathe operator's manual, M-codes chapter (its list as recalled; unchecked against a printed copy)";
constexpr std::string_view kHaasPost =
    "Autodesk HAAS lathe post processor (haas lathe.cps, getCode()), which writes it for this function";

// Haas lathes. M12–M15 are Haas's own (air blast, spindle brake), not live-tool codes; Haas's
// live tool is M133–M135 and its second spindle M143–M145, refused by name (gcode_table.cpp).
// Its parts catcher M35–M37 is in the common table: the part-off it catches is simulated.
// M23/M24 (thread chamfer on/off) change a thread's run-out and are not here.
constexpr std::array kHaas{
    MachineMCode{10, "chuck clamp", None, kHaasPost},
    MachineMCode{11, "chuck unclamp: the bar is free in the chuck", Unsimulated, kHaasPost},
    MachineMCode{12, "auto air jet on", None, kHaasPost},
    MachineMCode{13, "auto air jet off", None, kHaasPost},
    MachineMCode{14, "main spindle brake on", None, kHaasPost},
    MachineMCode{15, "main spindle brake off", None, kHaasPost},
    MachineMCode{17, "turret rotation forward", None, kHaasManual},
    MachineMCode{18, "turret rotation reverse", None, kHaasManual},
    MachineMCode{21, "tailstock advance", Unsimulated, kHaasPost},
    MachineMCode{22, "tailstock retract", Unsimulated, kHaasPost},
    MachineMCode{31, "chip auger forward", None, kHaasPost},
    MachineMCode{33, "chip auger stop", None, kHaasPost},
    MachineMCode{38, "spindle speed variation on", None, kHaasPost},
    MachineMCode{39, "spindle speed variation off", None, kHaasPost},
    MachineMCode{41, "spindle low gear", None, kHaasManual},
    MachineMCode{42, "spindle high gear", None, kHaasManual},
    // The user relays drive whatever the shop wired to them: a bar puller, a door, a gantry.
    MachineMCode{51, "user relay 1 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{52, "user relay 2 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{53, "user relay 3 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{54, "user relay 4 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{55, "user relay 5 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{56, "user relay 6 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{57, "user relay 7 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{58, "user relay 8 on (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{59, "output relay set (the shop's own equipment)", Unsimulated, kHaasManual},
    MachineMCode{61, "user relay 1 off", None, kHaasManual},
    MachineMCode{62, "user relay 2 off", None, kHaasManual},
    MachineMCode{63, "user relay 3 off", None, kHaasManual},
    MachineMCode{64, "user relay 4 off", None, kHaasManual},
    MachineMCode{65, "user relay 5 off", None, kHaasManual},
    MachineMCode{66, "user relay 6 off", None, kHaasManual},
    MachineMCode{67, "user relay 7 off", None, kHaasManual},
    MachineMCode{68, "user relay 8 off", None, kHaasManual},
    MachineMCode{69, "output relay clear", None, kHaasManual},
    MachineMCode{85, "automatic door open", None, kHaasPost},
    MachineMCode{86, "automatic door close", None, kHaasPost},
    MachineMCode{88, "coolant through the tool on", None, kHaasPost},
    MachineMCode{89, "coolant through the tool off", None, kHaasPost},
    MachineMCode{104, "probe arm extend", Unsimulated, kHaasManual},
    MachineMCode{105, "probe arm retract", Unsimulated, kHaasManual},
    MachineMCode{110, "secondary spindle chuck clamp", Unsimulated, kHaasPost},
    MachineMCode{111, "secondary spindle chuck unclamp", Unsimulated, kHaasPost},
};

constexpr std::array kFamilies{MachineMCodes::Gsk980tdi, MachineMCodes::Fanuc0iT, MachineMCodes::Haas};

}  // namespace

std::span<const MachineMCodes> machineMCodeFamilies() { return kFamilies; }

std::string_view machineMCodeFamilyName(MachineMCodes family) {
  switch (family) {
    case MachineMCodes::Gsk980tdi: return "gsk980tdi";
    case MachineMCodes::Fanuc0iT: return "fanuc-0i-t";
    case MachineMCodes::Haas: return "haas";
  }
  return "";
}

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

std::string machineMCodeMessage(const MachineMCode& code, std::string_view written) {
  if (code.motion == MachineMotion::None)
    return fmt::format("{} ({}) is a machine function that changes nothing simulated: ignored", written, code.meaning);
  return fmt::format("{} ({}) moves something lathesim does not simulate: the program runs on, but a collision "
                     "with it is not checked",
                     written, code.meaning);
}

}  // namespace lathesim::interp
