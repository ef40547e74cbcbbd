#include "tests/docs/code_reference.hpp"

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "interp/control/control_preset.hpp"
#include "interp/control/dialect.hpp"
#include "interp/control/gcode_table.hpp"
#include "interp/control/machine_m_codes.hpp"

namespace lathesim::docs {
namespace {

using namespace lathesim::interp;

// The largest code number a program can write (codes are read up to three digits).
constexpr int kLargestCode = 999;

// A table cell: Markdown would read a '|' as the next cell.
std::string cell(std::string_view text) {
  std::string escaped;
  for (char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

std::string status(bool supported, std::string_view lacks) {
  if (supported) return "simulated";
  if (!lacks.empty()) return fmt::format("refused: needs {}", lacks);
  return "refused: not read yet";
}

std::string gCodeTable(Dialect dialect) {
  std::string text = "| code | meaning | modal group | read |\n|---|---|---|---|\n";
  for (int written = 0; written <= kLargestCode; ++written) {
    const GCodeInfo* info = findGCode(written, dialect);
    if (info == nullptr) continue;
    std::string meaning(info->meaning);
    // A code written differently from system A names the system-A code it stands for.
    if (info->group != GGroup::Distance && info->number != written && info->supported)
      meaning += fmt::format(" (fanuc-a G{:02})", info->number);
    text += fmt::format("| G{:02} | {} | {} | {} |\n", written, cell(meaning), cell(groupName(info->group)),
                        cell(status(info->supported, info->lacks)));
  }
  return text;
}

std::string mCodeTable() {
  std::string text = "| code | meaning | group | read |\n|---|---|---|---|\n";
  for (int number = 0; number <= kLargestCode; ++number) {
    const MCodeInfo* info = findMCode(number);
    if (info == nullptr) continue;
    text += fmt::format("| M{:02} | {} | {} | {} |\n", number, cell(info->meaning), cell(groupName(info->group)),
                        cell(status(info->supported, info->lacks)));
  }
  return text;
}

std::string settingValue(const Control& control, std::string_view key) {
  for (const ControlSetting& setting : control.settings)
    if (setting.key == key) return parameterValueText(setting.value);
  return "";
}

std::string unquoted(std::string text) {
  text.erase(std::remove(text.begin(), text.end(), '"'), text.end());
  return text;
}

// Each list of machine M codes, with the presets that take it (m_codes).
std::string machineMCodeSection(const std::vector<Control>& controls) {
  std::map<std::string, std::vector<const Control*>> presetsOf;  // by the list's name
  std::map<std::string, MachineMCodes> listNamed;
  for (const Control& control : controls) {
    const std::string name = unquoted(settingValue(control, "m_codes"));
    presetsOf[name].push_back(&control);
    listNamed[name] = control.parameters.machineMCodes;
  }
  std::string text;
  for (const auto& [name, presets] : presetsOf) {
    std::string users;
    for (const Control* control : presets) users += fmt::format("{}`{}`", users.empty() ? "" : ", ", control->preset);
    text += fmt::format("#### `m_codes = \"{}\"` (preset {})\n\n| code | meaning |\n|---|---|\n", name, users);
    for (const MachineMCode& code : machineMCodes(listNamed[name]))
      text += fmt::format("| M{:02} | {} |\n", code.number, cell(code.meaning));
    text += '\n';
  }
  return text;
}

std::string presetOverview(const std::vector<Control>& controls) {
  std::string text = "| parameter |";
  std::string rule = "|---|";
  for (const Control& control : controls) {
    text += fmt::format(" `{}` |", control.preset);
    rule += "---|";
  }
  text += "\n" + rule + "\n";
  for (std::string_view key : controlParameterKeys()) {
    text += fmt::format("| `{}` |", key);
    for (const Control& control : controls) {
      const auto setting = std::find_if(control.settings.begin(), control.settings.end(),
                                        [&](const ControlSetting& s) { return s.key == key; });
      text += fmt::format(" {}{} |", cell(parameterValueText(setting->value)), setting->verified ? "" : " ⚠");
    }
    text += '\n';
  }
  return text;
}

std::string presetReferences(const Control& control) {
  std::string text = fmt::format("### Preset `{}`\n\n| parameter | value | where the value comes from |\n|---|---|---|\n",
                                 control.preset);
  for (const ControlSetting& setting : control.settings)
    text += fmt::format("| `{}` | {} | {}{} |\n", setting.key, cell(parameterValueText(setting.value)),
                        setting.verified ? "" : "⚠ ", cell(setting.manual));
  return text + '\n';
}

}  // namespace

std::string codeReference() {
  std::vector<Control> controls;
  for (std::string_view name : controlPresets()) controls.push_back(*controlPreset(name));

  std::string text = fmt::format(
      "# G- and M-code reference\n\n"
      "<!-- Generated from the interpreter's tables (interp/control/gcode_table.cpp,\n"
      "     machine_m_codes.cpp, control_preset.cpp) by\n"
      "       {}\n"
      "     and checked by tests/docs (a test fails when this file differs). Do not edit by hand. -->\n\n"
      "What lathesim reads, written out from the interpreter's own tables. *simulated*: the code is\n"
      "run; *refused*: the program stops with an error at the code, saying why. A code in none of\n"
      "these tables is an error naming the codes the dialect and control take. How each code is\n"
      "read (words, cycles, macros) is in [interpreter.md](interpreter.md); the controls' parameters\n"
      "in [controls.md](controls.md).\n\n",
      kRegenerateCodeReference);

  text += "## G codes, by dialect\n\n"
          "The dialect (`--dialect`, `[machine] dialect`) is how the program writes its codes. Every\n"
          "dialect maps its codes onto the same meanings, those of Fanuc/GSK system A (`fanuc-a`).\n\n";
  for (Dialect dialect : kDialects)
    text += fmt::format("### Dialect `{}`\n\n{}\n", dialectName(dialect), gCodeTable(dialect));

  text += "## M codes\n\n"
          "### Every control\n\n" +
          mCodeTable() +
          "\nM97 is read under the `haas` dialect only.\n\n"
          "### The machine's own M codes, by control\n\n"
          "Chuck, tailstock, conveyor, door, gear range …: a code on the control's list (parameter\n"
          "`m_codes`) changes nothing simulated; it is accepted and listed once in report.json's\n"
          "`notes`. It is looked up before the table above, so a control's own meaning wins (Haas's\n"
          "M13–M15 are its air jet and spindle clamp, not live-tool codes).\n\n" +
          machineMCodeSection(controls);

  text += "## Control presets\n\n"
          "`--control` or `[control] name` picks a preset; any parameter may be overridden in the\n"
          "setup's `[control]`. ⚠ marks a value not checked against the control's manual.\n\n" +
          presetOverview(controls) + "\n## Where each preset's values come from\n\n";
  for (const Control& control : controls) text += presetReferences(control);
  text.pop_back();  // one newline at the end of the file
  return text;
}

}  // namespace lathesim::docs
