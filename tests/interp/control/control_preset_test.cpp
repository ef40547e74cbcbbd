// The control presets and their parameters (interp/control/control_preset.hpp).

#include "interp/control/control_preset.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>

namespace lathesim::interp {
namespace {

const ControlSetting& settingOf(const Control& control, std::string_view key) {
  const auto found = std::find_if(control.settings.begin(), control.settings.end(),
                                  [&](const ControlSetting& s) { return s.key == key; });
  if (found == control.settings.end()) throw std::runtime_error("no setting " + std::string(key));
  return *found;
}

TEST(ControlPreset, EveryPresetGivesEveryParameterWithItsManualReference) {
  const std::vector<std::string_view> keys = controlParameterKeys();
  ASSERT_EQ(controlPresets(), (std::vector<std::string_view>{"gsk980tdi", "fanuc-0i-t", "haas", "denford"}));
  for (std::string_view name : controlPresets()) {
    SCOPED_TRACE(name);
    const std::optional<Control> control = controlPreset(name);  // throws on a gap in the table
    ASSERT_TRUE(control);
    EXPECT_EQ(control->preset, name);
    ASSERT_EQ(control->settings.size(), keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
      EXPECT_EQ(control->settings[i].key, keys[i]);
      EXPECT_FALSE(control->settings[i].manual.empty()) << keys[i];
      EXPECT_EQ(control->settings[i].source, "preset");
    }
  }
  EXPECT_FALSE(controlPreset("fanuc-0i-m"));
}

TEST(ControlPreset, TheDefaultParametersAreTheGsk980tdiPresets) {
  // ControlParameters{} is what InterpreterOptions starts from: it must be the default preset.
  const ControlParameters defaults;
  const ControlParameters gsk = controlPreset(kDefaultControlPreset)->parameters;
  EXPECT_EQ(defaults.rapidPath, gsk.rapidPath);
  EXPECT_EQ(defaults.decimalPointInput, gsk.decimalPointInput);
  EXPECT_EQ(defaults.leastIncrementMm, gsk.leastIncrementMm);
  EXPECT_EQ(defaults.incrementWordInput, gsk.incrementWordInput);
  EXPECT_EQ(defaults.blockSkip, gsk.blockSkip);
  EXPECT_EQ(defaults.powerOnFeedMode, gsk.powerOnFeedMode);
  EXPECT_EQ(defaults.roughingRetractAtFeed, gsk.roughingRetractAtFeed);
  EXPECT_EQ(defaults.peckXWordsAreDiameters, gsk.peckXWordsAreDiameters);
  EXPECT_EQ(defaults.peckReliefWithoutShift, gsk.peckReliefWithoutShift);
  EXPECT_EQ(defaults.patternSinglePass, gsk.patternSinglePass);
  EXPECT_EQ(defaults.arcEndOffCircle, gsk.arcEndOffCircle);
  EXPECT_EQ(defaults.arcRadiusToleranceMm, gsk.arcRadiusToleranceMm);
  EXPECT_EQ(defaults.offsetAfterReturn, gsk.offsetAfterReturn);
  EXPECT_EQ(defaults.absoluteWithIncremental, gsk.absoluteWithIncremental);
  EXPECT_EQ(defaults.drawingAngleWord, gsk.drawingAngleWord);
  EXPECT_EQ(defaults.cornerWords, gsk.cornerWords);
  EXPECT_EQ(defaults.chamferSize, gsk.chamferSize);
  EXPECT_EQ(defaults.toolWordForms, gsk.toolWordForms);
  EXPECT_EQ(defaults.roughingDepthMm, gsk.roughingDepthMm);
  EXPECT_EQ(defaults.roughingRetractMm, gsk.roughingRetractMm);
  EXPECT_EQ(defaults.patternReliefXMm, gsk.patternReliefXMm);
  EXPECT_EQ(defaults.patternReliefZMm, gsk.patternReliefZMm);
  EXPECT_EQ(defaults.patternPasses, gsk.patternPasses);
  EXPECT_EQ(defaults.peckRetractMm, gsk.peckRetractMm);
  EXPECT_EQ(defaults.threadFinishingPasses, gsk.threadFinishingPasses);
  EXPECT_EQ(defaults.threadToolAngleDeg, gsk.threadToolAngleDeg);
  EXPECT_EQ(defaults.threadMinDepthMm, gsk.threadMinDepthMm);
  EXPECT_EQ(defaults.threadAllowanceMm, gsk.threadAllowanceMm);
  EXPECT_EQ(defaults.threadRunoutLeads, gsk.threadRunoutLeads);
  EXPECT_EQ(defaults.threadEWord, gsk.threadEWord);
}

// The thread parameters: G76's first-block values and the run-out, each the control's own
// parameter (GSK No.57–60 and No.19; Fanuc 5142, 5143, 5140, 5141 and 5130, ⚠ values), and E,
// which the GSK980TDi's thread formats do not have.
TEST(ControlPreset, ThreadParametersNameTheirManualParameters) {
  const Control gsk = *controlPreset("gsk980tdi");
  const Control fanuc = *controlPreset("fanuc-0i-t");
  for (const auto& [key, gskNumber, fanucNumber] :
       {std::tuple{"g76_finishing_passes", "No.57", "5142"}, {"g76_tool_angle", "No.58", "5143"},
        {"g76_min_depth", "No.59", "5140"}, {"g76_allowance", "No.60", "5141"}, {"thread_runout", "No.19", "5130"}}) {
    EXPECT_NE(settingOf(gsk, key).manual.find(gskNumber), std::string::npos) << key;
    EXPECT_NE(settingOf(fanuc, key).manual.find(fanucNumber), std::string::npos) << key;
  }
  EXPECT_EQ(gsk.parameters.threadEWord, ThreadEWord::None);
  EXPECT_TRUE(settingOf(gsk, "thread_e_word").verified);
  EXPECT_EQ(fanuc.parameters.threadEWord, ThreadEWord::Lead);
  EXPECT_FALSE(settingOf(fanuc, "thread_e_word").verified);
  Control control = gsk;
  EXPECT_EQ(control.set("g76_tool_angle", 29.5, "setup"),
            "control.g76_tool_angle must be a whole number from 0 to 99, got 29.5");
  EXPECT_EQ(control.set("thread_e_word", std::string("tpi"), "setup"),
            "control.thread_e_word must be one of \"none\", \"lead\", \"threads_per_inch\", got \"tpi\"");
  EXPECT_EQ(control.set("g76_finishing_passes", 3.0, "setup"), std::nullopt);
  EXPECT_EQ(control.parameters.threadFinishingPasses, 3);
}

// lathe-cycles.md §10: what the two controls do differently.
TEST(ControlPreset, TheTwoControlsDifferWhereTheManualsSay) {
  const Control gsk = *controlPreset("gsk980tdi");
  const Control fanuc = *controlPreset("fanuc-0i-t");
  EXPECT_EQ(gsk.parameters.rapidPath, RapidPath::NonLinear);
  EXPECT_EQ(fanuc.parameters.rapidPath, RapidPath::NonLinear);
  EXPECT_EQ(gsk.parameters.decimalPointInput, DecimalPointInput::Calculator);
  EXPECT_EQ(fanuc.parameters.decimalPointInput, DecimalPointInput::LeastIncrements);  // DPI = 0
  EXPECT_EQ(gsk.parameters.powerOnFeedMode, FeedMode::PerMinute);                      // G98
  EXPECT_EQ(fanuc.parameters.powerOnFeedMode, FeedMode::PerRevolution);                // G99
  EXPECT_TRUE(gsk.parameters.roughingRetractAtFeed);
  EXPECT_FALSE(fanuc.parameters.roughingRetractAtFeed);
  EXPECT_TRUE(gsk.parameters.peckXWordsAreDiameters);
  EXPECT_FALSE(fanuc.parameters.peckXWordsAreDiameters);
  EXPECT_EQ(gsk.parameters.offsetAfterReturn, OffsetAfterReturn::Cancelled);
  EXPECT_EQ(fanuc.parameters.offsetAfterReturn, OffsetAfterReturn::Kept);
  EXPECT_EQ(settingOf(gsk, "rapid_positioning").manual, "GSK No.1#7 = 0 (§3.2; G28 legs §3.15 note 3)");
  EXPECT_TRUE(settingOf(gsk, "rapid_positioning").verified);
  EXPECT_EQ(settingOf(fanuc, "decimal_point_input").manual,
            "Fanuc 3401#0 DPI = 0 (DPI = 1 is calculator input, B-62764EN §5; its factory value assumed)");
  EXPECT_FALSE(settingOf(fanuc, "decimal_point_input").verified);  // the factory value: B-64604EN was not at hand
  EXPECT_TRUE(settingOf(fanuc, "g28_tool_offset").verified);       // 0i-TC B-64114EN §14.1.6
  EXPECT_EQ(std::get<std::string>(settingOf(fanuc, "power_on_feed_mode").value), "G99");
}

TEST(ControlPreset, SettingAParameterChangesItAndSaysWho) {
  Control control = *controlPreset("gsk980tdi");
  EXPECT_FALSE(control.set("rapid_positioning", std::string("linear"), "setup"));
  EXPECT_EQ(control.parameters.rapidPath, RapidPath::Linear);
  EXPECT_EQ(std::get<std::string>(settingOf(control, "rapid_positioning").value), "linear");
  EXPECT_EQ(settingOf(control, "rapid_positioning").source, "setup");
  EXPECT_FALSE(control.set("least_increment", 0.0001, "setup"));
  EXPECT_EQ(control.parameters.leastIncrementMm, 0.0001);
  EXPECT_FALSE(control.set("block_skip", std::string("off"), "command line"));
  EXPECT_FALSE(control.parameters.blockSkip);
  EXPECT_FALSE(control.set("g73_passes", 3.0, "setup"));
  EXPECT_EQ(control.parameters.patternPasses, 3);
  EXPECT_FALSE(control.set("tool_word", std::vector<std::string>{"3+3", "2+2"}, "setup"));
  EXPECT_EQ(control.parameters.toolWordForms, (std::vector<std::string>{"3+3", "2+2"}));
}

TEST(ControlPreset, AWrongKeyOrValueIsNamedWithWhatWasExpected) {
  Control control = *controlPreset("gsk980tdi");
  EXPECT_EQ(control.set("rapid", std::string("linear"), "setup").value().rfind("unknown key 'control.rapid' (expected "
                                                                               "name or one of rapid_positioning, ",
                                                                               0),
            0u);
  EXPECT_EQ(control.set("rapid_positioning", std::string("straight"), "setup"),
            "control.rapid_positioning must be one of \"nonlinear\", \"linear\", got \"straight\"");
  EXPECT_EQ(control.set("rapid_positioning", 1.0, "setup"),
            "control.rapid_positioning must be one of \"nonlinear\", \"linear\", got 1");
  EXPECT_EQ(control.set("least_increment", 0.01, "setup"), "control.least_increment must be 0.001 or 0.0001, got 0.01");
  EXPECT_EQ(control.set("g73_passes", 2.5, "setup"), "control.g73_passes must be a whole number from 1 to 9999, got 2.5");
  EXPECT_EQ(control.set("tool_word", std::vector<std::string>{"2+3"}, "setup"),
            "control.tool_word must be a list of one or more of \"2+2\", \"3+3\", \"haas\", got [\"2+3\"]");
  // Nothing changed.
  EXPECT_EQ(control.parameters.rapidPath, RapidPath::NonLinear);
  EXPECT_EQ(settingOf(control, "rapid_positioning").source, "preset");
}

}  // namespace
}  // namespace lathesim::interp
