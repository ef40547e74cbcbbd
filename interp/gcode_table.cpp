#include "interp/gcode_table.hpp"

#include <array>

namespace lathesim::interp {
namespace {

constexpr std::array kGCodes{
    GCodeInfo{0, GGroup::Motion, true, "rapid positioning"},
    GCodeInfo{1, GGroup::Motion, true, "linear feed"},
    GCodeInfo{2, GGroup::Motion, false, "clockwise arc"},
    GCodeInfo{3, GGroup::Motion, false, "counter-clockwise arc"},
    GCodeInfo{4, GGroup::NonModal, true, "dwell"},
    GCodeInfo{10, GGroup::NonModal, false, "data setting"},
    GCodeInfo{17, GGroup::Plane, true, "XY plane"},
    GCodeInfo{18, GGroup::Plane, true, "ZX plane"},
    GCodeInfo{19, GGroup::Plane, true, "YZ plane"},
    GCodeInfo{20, GGroup::Units, true, "inch input"},
    GCodeInfo{21, GGroup::Units, true, "metric input"},
    GCodeInfo{28, GGroup::NonModal, true, "reference point return"},
    GCodeInfo{32, GGroup::Motion, false, "thread cutting"},
    GCodeInfo{40, GGroup::NoseRadius, false, "nose radius compensation cancel"},
    GCodeInfo{41, GGroup::NoseRadius, false, "nose radius compensation left"},
    GCodeInfo{42, GGroup::NoseRadius, false, "nose radius compensation right"},
    GCodeInfo{50, GGroup::NonModal, true, "coordinate system setting"},
    GCodeInfo{65, GGroup::NonModal, false, "macro call"},
    GCodeInfo{70, GGroup::NonModal, false, "finishing cycle"},
    GCodeInfo{71, GGroup::NonModal, false, "OD/ID roughing cycle"},
    GCodeInfo{72, GGroup::NonModal, false, "face roughing cycle"},
    GCodeInfo{73, GGroup::NonModal, false, "pattern repeating cycle"},
    GCodeInfo{74, GGroup::NonModal, false, "face peck drilling cycle"},
    GCodeInfo{75, GGroup::NonModal, false, "grooving cycle"},
    GCodeInfo{76, GGroup::NonModal, false, "multiple threading cycle"},
    GCodeInfo{90, GGroup::Motion, true, "axial cutting cycle"},
    GCodeInfo{92, GGroup::Motion, false, "threading cycle"},
    GCodeInfo{94, GGroup::Motion, true, "face cutting cycle"},
    GCodeInfo{96, GGroup::SpindleMode, true, "constant surface speed"},
    GCodeInfo{97, GGroup::SpindleMode, true, "constant spindle speed"},
    GCodeInfo{98, GGroup::FeedMode, true, "feed per minute"},
    GCodeInfo{99, GGroup::FeedMode, true, "feed per revolution"},
};

constexpr std::array kMCodes{
    MCodeInfo{0, MGroup::Stop, false, "program stop"},
    MCodeInfo{1, MGroup::Stop, false, "optional stop"},
    MCodeInfo{2, MGroup::ProgramEnd, true, "end of program"},
    MCodeInfo{3, MGroup::Spindle, true, "spindle clockwise"},
    MCodeInfo{4, MGroup::Spindle, true, "spindle counter-clockwise"},
    MCodeInfo{5, MGroup::Spindle, true, "spindle stop"},
    MCodeInfo{8, MGroup::Coolant, true, "coolant on"},
    MCodeInfo{9, MGroup::Coolant, true, "coolant off"},
    MCodeInfo{30, MGroup::ProgramEnd, true, "end of program and rewind"},
    MCodeInfo{98, MGroup::Subprogram, false, "subprogram call"},
    MCodeInfo{99, MGroup::Subprogram, false, "subprogram return"},
};

}  // namespace

const GCodeInfo* findGCode(int number) {
  for (const auto& code : kGCodes) {
    if (code.number == number) return &code;
  }
  return nullptr;
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
    case GGroup::FeedMode: return "feed mode (G98/G99)";
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
  }
  return "unknown";
}

}  // namespace lathesim::interp
