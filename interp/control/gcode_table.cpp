#include "interp/control/gcode_table.hpp"

#include <algorithm>
#include <array>
#include <span>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

constexpr std::array kGCodes{
    GCodeInfo{0, GGroup::Motion, true, "rapid positioning"},
    GCodeInfo{1, GGroup::Motion, true, "linear feed"},
    GCodeInfo{2, GGroup::Motion, true, "clockwise arc"},
    GCodeInfo{3, GGroup::Motion, true, "counter-clockwise arc"},
    GCodeInfo{4, GGroup::NonModal, true, "dwell"},
    GCodeInfo{10, GGroup::NonModal, true, "data setting"},
    GCodeInfo{14, GGroup::NonModal, false, "secondary spindle swap", "a second spindle"},
    GCodeInfo{15, GGroup::NonModal, false, "secondary spindle swap cancel", "a second spindle"},
    GCodeInfo{17, GGroup::Plane, true, "XY plane"},
    GCodeInfo{18, GGroup::Plane, true, "ZX plane"},
    GCodeInfo{19, GGroup::Plane, true, "YZ plane"},
    GCodeInfo{20, GGroup::Units, true, "inch input"},
    GCodeInfo{21, GGroup::Units, true, "metric input"},
    GCodeInfo{28, GGroup::NonModal, true, "reference point return"},
    GCodeInfo{30, GGroup::NonModal, true, "second reference point return"},
    GCodeInfo{32, GGroup::Motion, true, "thread cutting"},
    GCodeInfo{40, GGroup::NoseRadius, true, "nose radius compensation cancel"},
    GCodeInfo{41, GGroup::NoseRadius, true, "nose radius compensation left"},
    GCodeInfo{42, GGroup::NoseRadius, true, "nose radius compensation right"},
    GCodeInfo{50, GGroup::NonModal, true, "coordinate system setting"},
    GCodeInfo{53, GGroup::NonModal, true, "move in machine coordinates"},
    GCodeInfo{54, GGroup::WorkCoordinates, true, "work coordinate system 1"},
    GCodeInfo{55, GGroup::WorkCoordinates, true, "work coordinate system 2"},
    GCodeInfo{56, GGroup::WorkCoordinates, true, "work coordinate system 3"},
    GCodeInfo{57, GGroup::WorkCoordinates, true, "work coordinate system 4"},
    GCodeInfo{58, GGroup::WorkCoordinates, true, "work coordinate system 5"},
    GCodeInfo{59, GGroup::WorkCoordinates, true, "work coordinate system 6"},
    GCodeInfo{65, GGroup::NonModal, true, "macro call"},
    GCodeInfo{70, GGroup::NonModal, true, "finishing cycle"},
    GCodeInfo{71, GGroup::NonModal, true, "OD/ID roughing cycle"},
    GCodeInfo{72, GGroup::NonModal, true, "face roughing cycle"},
    GCodeInfo{73, GGroup::NonModal, true, "pattern repeating cycle"},
    GCodeInfo{74, GGroup::NonModal, true, "face peck drilling cycle"},
    GCodeInfo{75, GGroup::NonModal, true, "grooving cycle"},
    GCodeInfo{76, GGroup::NonModal, true, "multiple threading cycle"},
    GCodeInfo{80, GGroup::DrillingCycle, true, "drilling cycle cancel"},
    GCodeInfo{81, GGroup::DrillingCycle, true, "drilling cycle on the axis"},
    GCodeInfo{82, GGroup::DrillingCycle, true, "spot drilling cycle on the axis (dwell at the bottom)"},
    GCodeInfo{83, GGroup::DrillingCycle, true, "peck drilling cycle on the axis"},
    GCodeInfo{84, GGroup::DrillingCycle, true, "tapping cycle on the axis"},
    GCodeInfo{87, GGroup::NonModal, false, "side drilling cycle", "live tooling (a driven tool drills radial holes)"},
    GCodeInfo{88, GGroup::NonModal, false, "side tapping cycle", "live tooling (a driven tool taps radial holes)"},
    GCodeInfo{89, GGroup::NonModal, false, "side boring cycle", "live tooling (a driven tool bores radial holes)"},
    GCodeInfo{90, GGroup::Motion, true, "axial cutting cycle"},
    GCodeInfo{92, GGroup::Motion, true, "threading cycle"},
    GCodeInfo{94, GGroup::Motion, true, "face cutting cycle"},
    GCodeInfo{96, GGroup::SpindleMode, true, "constant surface speed"},
    GCodeInfo{97, GGroup::SpindleMode, true, "constant spindle speed"},
    GCodeInfo{98, GGroup::FeedMode, true, "feed per minute"},
    GCodeInfo{99, GGroup::FeedMode, true, "feed per revolution"},
    GCodeInfo{112, GGroup::NonModal, false, "polar coordinate interpolation",
              "a C axis and live tooling (polar interpolation mills the face with a driven tool)"},
    GCodeInfo{113, GGroup::NonModal, false, "polar coordinate interpolation cancel",
              "a C axis and live tooling (polar interpolation mills the face with a driven tool)"},
};

constexpr std::array kMCodes{
    MCodeInfo{0, MGroup::Stop, true, "program stop"},
    MCodeInfo{1, MGroup::Stop, true, "optional stop"},
    MCodeInfo{2, MGroup::ProgramEnd, true, "end of program"},
    MCodeInfo{3, MGroup::Spindle, true, "spindle clockwise"},
    MCodeInfo{4, MGroup::Spindle, true, "spindle counter-clockwise"},
    MCodeInfo{5, MGroup::Spindle, true, "spindle stop"},
    // School trainers (Denford VR Turning, Boxford, Emco) write M06 beside the T word, in either
    // order (M06 T0101, T01 M06): the tool change the T word makes on its own elsewhere.
    MCodeInfo{6, MGroup::ToolChange, true, "tool change (Denford/Boxford/Emco trainers)"},
    MCodeInfo{8, MGroup::Coolant, true, "coolant on"},
    MCodeInfo{9, MGroup::Coolant, true, "coolant off"},
    MCodeInfo{13, MGroup::Spindle, false, "live tool on (Doosan/Fanuc; spindle and coolant on some older controls: write M03 M08)",
              "live tooling (a driven tool spindle)"},
    MCodeInfo{14, MGroup::Spindle, false, "live tool reverse", "live tooling (a driven tool spindle)"},
    MCodeInfo{15, MGroup::Spindle, false, "live tool stop", "live tooling (a driven tool spindle)"},
    MCodeInfo{30, MGroup::ProgramEnd, true, "end of program and rewind"},
    MCodeInfo{35, MGroup::PartsCatcher, true, "parts catcher to the part-off position (Haas)"},
    MCodeInfo{36, MGroup::PartsCatcher, true, "parts catcher on (Haas)"},
    MCodeInfo{37, MGroup::PartsCatcher, true, "parts catcher off (Haas)"},
    MCodeInfo{97, MGroup::Subprogram, true, "local subprogram call (Haas)"},
    MCodeInfo{98, MGroup::Subprogram, true, "subprogram call"},
    MCodeInfo{99, MGroup::Subprogram, true, "subprogram return"},
    MCodeInfo{133, MGroup::Spindle, false, "live tool forward (Haas)", "live tooling (a driven tool spindle)"},
    MCodeInfo{134, MGroup::Spindle, false, "live tool reverse (Haas)", "live tooling (a driven tool spindle)"},
    MCodeInfo{135, MGroup::Spindle, false, "live tool stop (Haas)", "live tooling (a driven tool spindle)"},
    MCodeInfo{143, MGroup::Spindle, false, "secondary spindle forward (Haas)", "a second spindle"},
    MCodeInfo{144, MGroup::Spindle, false, "secondary spindle reverse (Haas)", "a second spindle"},
    MCodeInfo{145, MGroup::Spindle, false, "secondary spindle stop (Haas)", "a second spindle"},
    MCodeInfo{154, MGroup::Spindle, false, "C axis engage (Haas)", "a C axis"},
    MCodeInfo{155, MGroup::Spindle, false, "C axis disengage (Haas)", "a C axis"},
};

// Absolute / incremental distance modes: only dialects that write G90/G91 have them.
constexpr std::array kDistanceCodes{
    GCodeInfo{kAbsoluteDistance, GGroup::Distance, true, "absolute distance mode"},
    GCodeInfo{kIncrementalDistance, GGroup::Distance, true, "incremental distance mode"},
};

// HNC writes the compound cycles in a one-block form of its own (e.g. G71 U R P Q X Z F):
// the same numbers as system A with other words, which lathesim does not read yet (its G76 it
// reads: interp/cycles/compound_cycle.cpp).
constexpr std::array kHncOwnCompoundCycles{
    GCodeInfo{70, GGroup::NonModal, false, "finishing cycle; hnc's form is not read yet"},
    GCodeInfo{71, GGroup::NonModal, false, "OD/ID roughing cycle in hnc's one-block form"},
    GCodeInfo{72, GGroup::NonModal, false, "face roughing cycle in hnc's one-block form"},
    GCodeInfo{73, GGroup::NonModal, false, "pattern repeating cycle in hnc's one-block form"},
    GCodeInfo{74, GGroup::NonModal, false, "face peck drilling cycle in hnc's form"},
    GCodeInfo{75, GGroup::NonModal, false, "grooving cycle in hnc's form"},
};

// A code a dialect writes differently from system A. `meaning` is the system-A number,
// or one of these:
constexpr int kNoSuchCode = -1;  // the dialect has no such code (or another, non-lathe one)
constexpr int kAbsolute = -2;
constexpr int kIncremental = -3;
constexpr int kHncOwn = -4;  // see kHncOwnCompoundCycles
struct Renumbered {
  int written;
  int meaning;
};

// Fanuc 0i-T G-code system B (Fanuc's table of G-code systems A/B/C).
constexpr std::array kFanucB{
    Renumbered{77, 90}, Renumbered{78, 92}, Renumbered{79, 94}, Renumbered{33, 32},
    Renumbered{92, 50}, Renumbered{94, 98}, Renumbered{95, 99}, Renumbered{90, kAbsolute},
    Renumbered{91, kIncremental}, Renumbered{32, kNoSuchCode}, Renumbered{50, kNoSuchCode},
    Renumbered{98, kNoSuchCode}, Renumbered{99, kNoSuchCode},  // canned-drilling return levels
};

// Huazhong HNC-21T/818T lathes.
constexpr std::array kHnc{
    Renumbered{80, 90}, Renumbered{82, 92}, Renumbered{81, 94}, Renumbered{92, 50},
    Renumbered{94, 98}, Renumbered{95, 99}, Renumbered{90, kAbsolute}, Renumbered{91, kIncremental},
    Renumbered{50, kNoSuchCode}, Renumbered{98, kNoSuchCode}, Renumbered{99, kNoSuchCode},
    Renumbered{70, kHncOwn}, Renumbered{71, kHncOwn}, Renumbered{72, kHncOwn}, Renumbered{73, kHncOwn},
    Renumbered{74, kHncOwn}, Renumbered{75, kHncOwn},
};

std::span<const Renumbered> renumberingOf(Dialect dialect) {
  switch (dialect) {
    case Dialect::FanucA: return {};
    case Dialect::FanucB: return kFanucB;
    case Dialect::Hnc: return kHnc;
    case Dialect::Haas: return {};  // system A's numbers; the one-block cycle forms are read
                                    // by the cycles (haas_roughing.cpp, haas_g76.cpp)
  }
  return {};
}

template <class Table>
const GCodeInfo* entryNumbered(const Table& table, int number) {
  for (const auto& code : table)
    if (code.number == number) return &code;
  return nullptr;
}

}  // namespace

const GCodeInfo* findGCode(int written, Dialect dialect) {
  for (const Renumbered& r : renumberingOf(dialect)) {
    if (r.written != written) continue;
    switch (r.meaning) {
      case kNoSuchCode: return nullptr;
      case kAbsolute: return &kDistanceCodes[0];
      case kIncremental: return &kDistanceCodes[1];
      case kHncOwn: return entryNumbered(kHncOwnCompoundCycles, written);
      default: return entryNumbered(kGCodes, r.meaning);
    }
  }
  return entryNumbered(kGCodes, written);
}

std::string writtenGCode(int number, GGroup group, Dialect dialect) {
  for (int written = 0; written <= 999; ++written) {
    const GCodeInfo* info = findGCode(written, dialect);
    if (info != nullptr && info->number == number && info->group == group) return fmt::format("G{:02}", written);
  }
  return fmt::format("G{:02}", number);
}

char cycleTaperLetter(int cycle, Dialect dialect) {
  if (dialect != Dialect::Hnc) return 'R';
  return cycle == 94 ? 'K' : 'I';
}

std::string supportedGCodes(Dialect dialect) {
  // Listed once per dialect: a list walks every number a G word can have, and every unknown
  // G code of a program asks for it.
  static const std::array<std::string, kDialects.size()> lists = [] {
    std::array<std::string, kDialects.size()> listed;
    for (std::size_t d = 0; d < kDialects.size(); ++d)
      for (int written = 0; written <= 999; ++written) {
        const GCodeInfo* info = findGCode(written, kDialects[d]);
        if (info != nullptr && info->supported)
          listed[d] += fmt::format("{}G{:02}", listed[d].empty() ? "" : " ", written);
      }
    return listed;
  }();
  return lists[static_cast<std::size_t>(std::find(kDialects.begin(), kDialects.end(), dialect) - kDialects.begin())];
}

std::string supportedMCodes() {
  std::string list;
  for (const auto& code : kMCodes)
    if (code.supported) list += fmt::format("{}M{:02}", list.empty() ? "" : " ", code.number);
  return list;
}

const MCodeInfo* findMCode(int number) {
  for (const auto& code : kMCodes) {
    if (code.number == number) return &code;
  }
  return nullptr;
}
std::string_view groupName(GGroup group) {
  switch (group) {
    case GGroup::NonModal: return "one-shot (group 00)";
    case GGroup::Motion: return "motion (group 01)";
    case GGroup::Plane: return "plane selection";
    case GGroup::Units: return "unit (G20/G21)";
    case GGroup::NoseRadius: return "nose radius compensation";
    case GGroup::SpindleMode: return "spindle speed mode (G96/G97)";
    case GGroup::FeedMode: return "feed mode";
    case GGroup::Distance: return "distance mode (absolute/incremental)";
    case GGroup::WorkCoordinates: return "work coordinate system (G54–G59)";
    case GGroup::DrillingCycle: return "drilling cycle (group 10)";
  }
  return "unknown";
}

std::string_view groupName(MGroup group) {
  switch (group) {
    case MGroup::ProgramEnd: return "program end";
    case MGroup::Spindle: return "spindle";
    case MGroup::Coolant: return "coolant";
    case MGroup::Stop: return "program stop";
    case MGroup::Subprogram: return "subprogram";
    case MGroup::PartsCatcher: return "parts catcher";
    case MGroup::ToolChange: return "tool change";
  }
  return "unknown";
}

}  // namespace lathesim::interp
