// The parameter and preset tables (see control_preset.hpp). References: the GSK980TDi manual,
// chapter 3 (§) and its parameter list (No.), as lathe-cycles.md §10 cites them; Fanuc 0i-T
// parameter numbers are from general knowledge of the control (B-64604EN was not at hand),
// so a Fanuc entry is unverified unless it names the Fanuc manual page that says so.

#include "interp/control/control_preset.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

enum class ValueKind { Choice, Number, ChoiceList };

struct ParameterDefinition {
  std::string_view key;
  ValueKind kind;
  std::vector<std::string_view> choices;  // a choice: its names, in the order of its values
  double minimum = 0;                     // a number: its range, and whether it is whole
  double maximum = 0;
  bool whole = false;
  std::vector<double> allowed;            // a number limited to these values (empty: any in range)
  std::function<ParameterValue(const ControlParameters&)> get;
  std::function<void(ControlParameters&, const ParameterValue&)> set;
};

// A parameter that is an enum (or a bool: its true value named first) of ControlParameters.
template <auto Member>
ParameterDefinition choice(std::string_view key, std::vector<std::string_view> names) {
  using Value = std::remove_reference_t<decltype(std::declval<ControlParameters&>().*Member)>;
  const auto index = [](Value value) -> std::size_t {
    if constexpr (std::is_same_v<Value, bool>) return value ? 0 : 1;
    else return static_cast<std::size_t>(value);
  };
  const auto valueAt = [](std::size_t i) -> Value {
    if constexpr (std::is_same_v<Value, bool>) return i == 0;
    else return static_cast<Value>(i);
  };
  ParameterDefinition definition{key, ValueKind::Choice, names, 0, 0, false, {}, {}, {}};
  definition.get = [names, index](const ControlParameters& p) {
    return ParameterValue(std::string(names[index(p.*Member)]));
  };
  definition.set = [names, valueAt](ControlParameters& p, const ParameterValue& v) {
    const auto at = std::find(names.begin(), names.end(), std::get<std::string>(v));
    p.*Member = valueAt(static_cast<std::size_t>(at - names.begin()));
  };
  return definition;
}

// A parameter that is a number (double or int) of ControlParameters.
template <auto Member>
ParameterDefinition number(std::string_view key, double minimum, double maximum, bool whole = false,
                           std::vector<double> allowed = {}) {
  using Value = std::remove_reference_t<decltype(std::declval<ControlParameters&>().*Member)>;
  ParameterDefinition definition{key, ValueKind::Number, {}, minimum, maximum, whole, std::move(allowed), {}, {}};
  definition.get = [](const ControlParameters& p) { return ParameterValue(static_cast<double>(p.*Member)); };
  definition.set = [](ControlParameters& p, const ParameterValue& v) {
    p.*Member = static_cast<Value>(std::get<double>(v));
  };
  return definition;
}

// A parameter that is a list of names (std::vector<std::string>) of ControlParameters.
template <auto Member>
ParameterDefinition choiceList(std::string_view key, std::vector<std::string_view> names) {
  ParameterDefinition definition{key, ValueKind::ChoiceList, std::move(names), 0, 0, false, {}, {}, {}};
  definition.get = [](const ControlParameters& p) { return ParameterValue(p.*Member); };
  definition.set = [](ControlParameters& p, const ParameterValue& v) { p.*Member = std::get<std::vector<std::string>>(v); };
  return definition;
}

using P = ControlParameters;

// Every parameter: its key and values. What each means is in README.md ("The control").
const std::vector<ParameterDefinition>& parameterTable() {
  static const std::vector<ParameterDefinition> table{
      choice<&P::rapidPath>("rapid_positioning", {"nonlinear", "linear"}),
      choice<&P::decimalPointInput>("decimal_point_input", {"calculator", "increments"}),
      number<&P::leastIncrementMm>("least_increment", 0.0001, 0.001, false, {0.001, 0.0001}),
      choice<&P::incrementWordInput>("increment_words", {"increments", "calculator"}),
      choice<&P::blockSkip>("block_skip", {"on", "off"}),
      choice<&P::powerOnFeedMode>("power_on_feed_mode", {"G98", "G99"}),
      choice<&P::powerOnMetric>("power_on_units", {"G21", "G20"}),
      choice<&P::roughingRetractAtFeed>("g71_retract_at", {"feed", "rapid"}),
      choice<&P::peckXWordsAreDiameters>("g74_x_words", {"diameter", "radius"}),
      choice<&P::peckReliefWithoutShift>("g74_relief_without_shift", {"plus", "sign"}),
      choice<&P::patternSinglePass>("g73_single_pass", {"runs_twice", "runs_once"}),
      choice<&P::arcEndOffCircle>("arc_end_off_circle", {"move_centre", "alarm"}),
      number<&P::arcRadiusToleranceMm>("arc_radius_tolerance", 0.0, 1.0),
      choice<&P::offsetAfterReturn>("g28_tool_offset", {"cancel", "keep"}),
      choice<&P::absoluteWithIncremental>("absolute_and_incremental", {"absolute_wins", "alarm"}),
      choice<&P::drawingAngleWord>("drawing_angle_word", {"Q", "A", ",A"}),
      choice<&P::cornerWords>("corner_words", {"L/D", ",C/,R"}),
      choice<&P::chamferSize>("chamfer_size", {"chamfer_length", "from_corner"}),
      choiceList<&P::toolWordForms>("tool_word", {"2+2", "3+3", "haas"}),
      choice<&P::machineMCodes>("m_codes", {"gsk980tdi", "fanuc-0i-t", "haas"}),
      choice<&P::dwellPWord>("g04_p", {"milliseconds", "seconds_with_point"}),
      number<&P::roughingDepthMm>("g71_depth", 0.0, 1000.0),
      number<&P::roughingRetractMm>("g71_retract", 0.0, 1000.0),
      number<&P::patternReliefXMm>("g73_relief_x", -1000.0, 1000.0),
      number<&P::patternReliefZMm>("g73_relief_z", -1000.0, 1000.0),
      number<&P::patternPasses>("g73_passes", 1.0, 9999.0, true),
      number<&P::peckRetractMm>("g74_retract", 0.0, 1000.0),
      number<&P::threadFinishingPasses>("g76_finishing_passes", 0.0, 99.0, true),
      number<&P::threadToolAngleDeg>("g76_tool_angle", 0.0, 99.0, true),
      number<&P::threadMinDepthMm>("g76_min_depth", 0.0, 1000.0),
      number<&P::threadAllowanceMm>("g76_allowance", 0.0, 1000.0),
      number<&P::threadRunoutLeads>("thread_runout", 0.0, 9.9),
      number<&P::threadRunoutAngleDeg>("thread_runout_angle", 0.0, 89.0, true),
      choice<&P::threadEWord>("thread_e_word", {"none", "lead", "threads_per_inch"}),
      choice<&P::cutWithoutTool>("cut_without_tool", {"warning", "error"}),
  };
  return table;
}

const ParameterDefinition* findDefinition(std::string_view key) {
  for (const auto& definition : parameterTable())
    if (definition.key == key) return &definition;
  return nullptr;
}

struct PresetValue {
  std::string_view key;
  ParameterValue value;
  std::string_view manual;
  bool verified;
};

struct PresetDefinition {
  std::string_view name;
  std::optional<std::string_view> basedOn;  // take its values, then these
  std::vector<PresetValue> values;
};

using Names = std::vector<std::string>;

const std::vector<PresetDefinition>& presetTable() {
  static const std::vector<PresetDefinition> table{
      {"gsk980tdi",
       std::nullopt,
       {
           {"rapid_positioning", "nonlinear", "GSK No.1#7 = 0 (§3.2; G28 legs §3.15 note 3)", true},
           {"decimal_point_input", "calculator", "no such parameter: §3.2's examples write bare mm (G0 X20 Z25)", true},
           {"least_increment", 0.001, "GSK No.1#1 = 0 (IS-B)", true},
           {"increment_words", "increments", "GSK No.182#7 = 0", true},
           {"block_skip", "on", "block skip switch on the operator panel", true},
           {"power_on_feed_mode", "G98", "GSK No.182#0 = 0 (§3.26)", true},
           {"power_on_units", "G21", "a metric machine (GSK No.1#0 INM = 0); the factory value assumed", false},
           {"g71_retract_at", "feed", "§3.23.1 step 4", true},
           {"g74_x_words", "diameter", "§3.23.5, §3.23.6", true},
           {"g74_relief_without_shift", "plus", "§3.23.5 (X(U) and P omitted: toward +)", true},
           {"g73_single_pass", "runs_twice", "§3.23.3 (d = 1 cuts twice)", true},
           {"arc_end_off_circle", "move_centre", "§3.4 notes 5–6 (alarm only when the chord exceeds 2R)", true},
           {"arc_radius_tolerance", 0.01, "GSK No.154 (largest arc radius error); its value assumed", false},
           {"g28_tool_offset", "cancel", "GSK No.182#2 = 0 (§3.15 note 4)", true},
           {"absolute_and_incremental", "absolute_wins", "§3.2 (X, Z win over U, W)", true},
           {"drawing_angle_word", "Q", "§3.13 (Q, in 0.001° or in degrees by No.182#7)", true},
           {"corner_words", "L/D", "§3.11 (L chamfer, D corner radius)", true},
           {"chamfer_size", "chamfer_length", "GSK No.181#0 = 0 (§3.11.1, type I)", true},
           {"tool_word", Names{"2+2"}, "T: two digits of tool, two of offset", false},
           {"m_codes", "gsk980tdi", "GSK980TDi M codes (chuck, tailstock, lubrication, gears); the list unchecked", false},
           {"g04_p", "milliseconds", "§3.14 (P in ms)", true},
           {"g71_depth", 1.0, "GSK No.51; its factory value assumed", false},
           {"g71_retract", 0.5, "GSK No.52; its factory value assumed", false},
           {"g73_relief_x", 0.0, "GSK No.53; its factory value assumed", false},
           {"g73_relief_z", 0.0, "GSK No.54; its factory value assumed", false},
           {"g73_passes", 1.0, "GSK No.55; its factory value assumed", false},
           {"g74_retract", 0.5, "GSK No.56; its factory value assumed", false},
           {"g76_finishing_passes", 1.0, "GSK No.57; its factory value assumed", false},
           {"g76_tool_angle", 60.0, "GSK No.58; its factory value assumed", false},
           {"g76_min_depth", 0.0, "GSK No.59; its factory value assumed", false},
           {"g76_allowance", 0.0, "GSK No.60; its factory value assumed", false},
           {"thread_runout", 0.0, "GSK No.19 (in 0.1 lead); its factory value assumed", false},
           {"thread_runout_angle", 0.0, "GSK has none: without J and K, No.19 runs out as far along as across (45°)", true},
           {"thread_e_word", "none", "§3.24.1, §3.24.9, §3.24.12: the lead is F, or I in threads per inch; no E", true},
           {"cut_without_tool", "warning",
            "the turret keeps the tool it was left at (GSK980TDi: the current tool is shown and kept at power "
            "on); unchecked",
            false},
       }},
      {"fanuc-0i-t",
       std::nullopt,
       {
           {"rapid_positioning", "nonlinear", "Fanuc 1401#1 LRP = 0 (the bit: B-63944EN §4.1; its factory value assumed)", false},
           {"decimal_point_input", "increments", "Fanuc 3401#0 DPI = 0 (DPI = 1 is calculator input, B-62764EN §5; its factory value assumed)", false},
           {"least_increment", 0.001, "Fanuc 1004#1 ISC = 0 (IS-B; IS-C is an option)", false},
           {"increment_words", "increments", "no parameter: always least increments", false},
           {"block_skip", "on", "BDT switch on the operator panel", false},
           {"power_on_feed_mode", "G99", "Fanuc 3402#4 FPM = 0", false},
           {"power_on_units", "G21", "Fanuc 0001#2 INI = 0 (metric input); a metric machine assumed", false},
           {"g71_retract_at", "rapid", "Fanuc-style guides (Yaskawa LX3, Robur) draw it rapid", false},
           {"g74_x_words", "radius", "Fanuc figures draw Δi beside U/2", false},
           {"g74_relief_without_shift", "sign", "the sign of Δd gives the direction", false},
           {"g73_single_pass", "runs_once", "d = 1: one pass, at the allowance", false},
           {"arc_end_off_circle", "alarm", "Fanuc PS0020 beyond parameter 3410", false},
           {"arc_radius_tolerance", 0.01, "Fanuc 3410", false},
           {"g28_tool_offset", "keep", "0i-TC B-64114EN §14.1.6 (G28 does not cancel the offset vector)", true},
           {"absolute_and_incremental", "alarm", "X and U in one block alarm", false},
           {"drawing_angle_word", "A", "Fanuc 3405#4 CCR = 0 (A; ,A when 1)", false},
           {"corner_words", ",C/,R", "Fanuc chamfering and corner R", false},
           {"chamfer_size", "from_corner", ",C: from the corner along each line", false},
           {"tool_word", Names{"2+2"}, "Fanuc 5002#0 LD1 = 0: the offset in the last two digits", false},
           {"m_codes", "fanuc-0i-t", "the machine builder's M codes (common assignments)", false},
           {"g04_p", "milliseconds", "Fanuc G04 P in ms", false},
           {"g71_depth", 1.0, "Fanuc 5132; its value assumed", false},
           {"g71_retract", 0.5, "Fanuc 5133; its value assumed", false},
           {"g73_relief_x", 0.0, "Fanuc 5135; its value assumed", false},
           {"g73_relief_z", 0.0, "Fanuc 5136; its value assumed", false},
           {"g73_passes", 1.0, "Fanuc 5137; its value assumed", false},
           {"g74_retract", 0.5, "Fanuc 5139; its value assumed", false},
           {"g76_finishing_passes", 1.0, "Fanuc 5142; its value assumed", false},
           {"g76_tool_angle", 60.0, "Fanuc 5143; its value assumed", false},
           {"g76_min_depth", 0.0, "Fanuc 5140; its value assumed", false},
           {"g76_allowance", 0.0, "Fanuc 5141; its value assumed", false},
           {"thread_runout", 0.0, "Fanuc 5130 (in 0.1 lead); its value assumed", false},
           {"thread_runout_angle", 0.0, "Fanuc 5131 (0 means 45°); its value assumed", false},
           {"thread_e_word", "lead", "E the lead with more digits for inch threads (Fanuc 0-TD G34; 0i-T unchecked)", false},
           {"cut_without_tool", "warning",
            "a turret always has a station at the cutting position: the tool it was left at cuts, T□□00 only cancels "
            "the offset (a Fanuc-style lathe manual's T function); no manual found refuses a cut before a T word, so "
            "a warning; unchecked on a 0i-T",
            false},
       }},
      {"haas",
       "fanuc-0i-t",
       {
           {"rapid_positioning", "nonlinear", "Haas G00: each axis at its own rate (not checked in a Haas manual)", false},
           {"least_increment", 0.001, "Haas metric input 0.001 mm (0.0001 in)", false},
           {"decimal_point_input", "increments",
            "Haas Setting 162 Default To Float = Off: a value without a point is machinist's notation "
            "(haas.co.uk, 'Help with the decimal points'); Off as the factory value assumed",
            false},
           {"power_on_feed_mode", "G99", "Haas lathes power on in G99 (feed per revolution)", false},
           {"power_on_units", "G21", "Haas Setting 9 (dimensioning INCH/MM); a metric machine assumed", false},
           {"corner_words", ",C/,R", "Haas G01 ,C chamfer and ,R corner rounding", false},
           {"tool_word", Names{"haas"}, "Haas Tnnoo; T1 read as tool 1 with offset 1", false},
           {"m_codes", "haas", "the Haas lathe M-code list", false},
           {"g04_p", "seconds_with_point", "Haas G04: P10. dwells 10 s, P10 10 ms", false},
           {"g71_depth", 2.54, "Haas Setting 72 (canned cycle cut depth, 0.100 in)", false},
           {"g71_retract", 1.27,
            "Haas Setting 73 Can Cycle Retraction (staging-diy.haascnc.com, 'Type 2 details'); its value 0.050 in "
            "assumed",
            false},
           {"g76_min_depth", 0.0254, "Haas Setting 99 (thread minimum cut, 0.0010 in), the one-block G76's least depth a pass adds", false},
           {"g76_allowance", 0.0, "Haas Setting 86 (thread finish allowance), what the one-block G76's last pass removes", false},
           {"cut_without_tool", "warning",
            "the turret keeps the tool it was left at; no Haas manual found says a cut before a T word is refused, "
            "so a warning; unchecked",
            false},
       }},
      // School trainers (Denford's Fanuc-style turning software and the lathes it drives, and
      // Boxford's and Emco's alike): Fanuc's words, as their programs write them. No Denford
      // manual was at hand; each value says what it rests on.
      {"denford",
       "fanuc-0i-t",
       {
           {"decimal_point_input", "calculator",
            "trainer programs as published write bare millimetres (G00 X26 Z2 beside M06 T0101 and G94 X0 Z-0.5); "
            "unchecked against a Denford manual",
            false},
           {"tool_word", Names{"2+2"}, "M06 T0101: tool 1 with offset 1 (M06 T01, tool 1 with its own offset, is read "
                                       "as well, tool_word.hpp)", false},
           {"m_codes", "fanuc-0i-t",
            "no Denford M-code list at hand: the Fanuc builders' common codes; a trainer's own code is refused by name",
            false},
           {"cut_without_tool", "warning",
            "no source says the trainer's software refuses a cut before M06 names a tool: warned of, as on a lathe; "
            "set \"error\" in the setup's [control] for a trainer that refuses",
            false},
       }},
  };
  return table;
}

const PresetDefinition* findPreset(std::string_view name) {
  for (const auto& preset : presetTable())
    if (preset.name == name) return &preset;
  return nullptr;
}

std::string numberText(double value) { return fmt::format("{:g}", value); }

std::string joined(const std::vector<std::string_view>& names) {
  std::string text;
  for (std::string_view name : names) text += fmt::format("{}\"{}\"", text.empty() ? "" : ", ", name);
  return text;
}

// Why `value` cannot be `definition`'s value, or nullopt.
std::optional<std::string> valueProblem(const ParameterDefinition& definition, const ParameterValue& value) {
  const std::string key(definition.key);
  switch (definition.kind) {
    case ValueKind::Choice: {
      const auto* name = std::get_if<std::string>(&value);
      if (name && std::find(definition.choices.begin(), definition.choices.end(), *name) != definition.choices.end())
        return std::nullopt;
      return fmt::format("control.{} must be one of {}, got {}", key, joined(definition.choices),
                         parameterValueText(value));
    }
    case ValueKind::Number: {
      const auto* n = std::get_if<double>(&value);
      const bool inRange = n && std::isfinite(*n) && *n >= definition.minimum && *n <= definition.maximum &&
                           (!definition.whole || std::floor(*n) == *n);
      const bool allowed = n && (definition.allowed.empty() ||
                                 std::find(definition.allowed.begin(), definition.allowed.end(), *n) != definition.allowed.end());
      if (inRange && allowed) return std::nullopt;
      if (!definition.allowed.empty()) {
        std::string listed;
        for (double a : definition.allowed) listed += (listed.empty() ? "" : " or ") + numberText(a);
        return fmt::format("control.{} must be {}, got {}", key, listed, parameterValueText(value));
      }
      return fmt::format("control.{} must be a {}number from {} to {}, got {}", key, definition.whole ? "whole " : "",
                         numberText(definition.minimum), numberText(definition.maximum), parameterValueText(value));
    }
    case ValueKind::ChoiceList: {
      const auto* names = std::get_if<std::vector<std::string>>(&value);
      bool ok = names && !names->empty();
      for (std::size_t i = 0; ok && i < names->size(); ++i)
        ok = std::find(definition.choices.begin(), definition.choices.end(), (*names)[i]) != definition.choices.end();
      if (ok) return std::nullopt;
      return fmt::format("control.{} must be a list of one or more of {}, got {}", key, joined(definition.choices),
                         parameterValueText(value));
    }
  }
  return std::nullopt;
}

// The settings of `preset`, its base's first; every parameter must end up with a value.
void collect(const PresetDefinition& preset, std::vector<ControlSetting>& settings) {
  if (preset.basedOn) collect(*findPreset(*preset.basedOn), settings);
  for (const PresetValue& v : preset.values) {
    const auto found = std::find_if(settings.begin(), settings.end(), [&](const ControlSetting& s) { return s.key == v.key; });
    ControlSetting setting{std::string(v.key), v.value, std::string(v.manual), v.verified, "preset"};
    if (found != settings.end()) *found = setting;
    else settings.push_back(setting);
  }
}

}  // namespace

std::string parameterValueText(const ParameterValue& value) {
  if (const auto* name = std::get_if<std::string>(&value)) return fmt::format("\"{}\"", *name);
  if (const auto* n = std::get_if<double>(&value)) return numberText(*n);
  std::string text;
  for (const std::string& name : std::get<std::vector<std::string>>(value))
    text += fmt::format("{}\"{}\"", text.empty() ? "" : ", ", name);
  return "[" + text + "]";
}

std::optional<std::string> Control::set(std::string_view key, const ParameterValue& value, std::string_view source) {
  const ParameterDefinition* definition = findDefinition(key);
  if (definition == nullptr) {
    std::string keys;
    for (std::string_view k : controlParameterKeys()) keys += fmt::format("{}{}", keys.empty() ? "" : ", ", k);
    return fmt::format("unknown key 'control.{}' (expected name or one of {})", key, keys);
  }
  if (auto problem = valueProblem(*definition, value)) return problem;
  definition->set(parameters, value);
  for (ControlSetting& setting : settings) {
    if (setting.key != key) continue;
    setting.value = definition->get(parameters);
    setting.source = std::string(source);
  }
  return std::nullopt;
}

bool Control::knows(std::string_view key) const { return findDefinition(key) != nullptr; }

std::optional<Control> controlPreset(std::string_view name) {
  const PresetDefinition* preset = findPreset(name);
  if (preset == nullptr) return std::nullopt;
  std::vector<ControlSetting> byPreset;
  collect(*preset, byPreset);
  Control control{std::string(name), {}, {}};
  // In the parameter table's order; a parameter the preset does not give is a broken table.
  for (const ParameterDefinition& definition : parameterTable()) {
    const auto found = std::find_if(byPreset.begin(), byPreset.end(),
                                    [&](const ControlSetting& s) { return s.key == definition.key; });
    if (found == byPreset.end() || valueProblem(definition, found->value))
      throw std::logic_error(fmt::format("control preset {} gives no valid {}", name, definition.key));
    definition.set(control.parameters, found->value);
    control.settings.push_back(*found);
  }
  return control;
}

std::vector<std::string_view> controlPresets() {
  std::vector<std::string_view> names;
  for (const auto& preset : presetTable()) names.push_back(preset.name);
  return names;
}

std::vector<std::string_view> controlParameterKeys() {
  std::vector<std::string_view> keys;
  for (const auto& definition : parameterTable()) keys.push_back(definition.key);
  return keys;
}

}  // namespace lathesim::interp
