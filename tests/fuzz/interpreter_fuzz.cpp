// libFuzzer harness: a whole program interpreted — cycles, subprograms (M98 within the text),
// Custom Macro B (variables, expressions, loops, G65), compensation, corners, travel — under a dialect and control preset the first bytes choose,
// then timed and written as toolpath.csv, as a run does. Errors are answers; a crash, a hang,
// a leak or undefined behaviour is a finding.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <vector>

#include "interp/control/control_preset.hpp"
#include "interp/interpreter.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/output/toolpath_csv.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace lathesim;
using namespace lathesim::interp;

namespace {

InterpreterOptions optionsFrom(fuzz::FuzzInput& input) {
  InterpreterOptions options;
  options.startPosition = RZ(100.0, 200.0);
  options.toolNumbers = {1, 2, 3, 4};
  options.dialect = kDialects[input.choice(kDialects.size())];
  // The presets' parameters built once: building them took a sixth of the harness's time.
  static const std::vector<ControlParameters> presets = [] {
    std::vector<ControlParameters> all;
    for (std::string_view name : controlPresets()) all.push_back(controlPreset(name)->parameters);
    return all;
  }();
  options.control = presets[input.choice(static_cast<unsigned>(presets.size()))];
  options.control.blockSkip = input.choice(2) == 0;
  // Offsets with nose radii and tips, so G41/G42 compensate for real.
  options.offsets[1] = ToolOffset{0.0, 0.0, 0.8, 3, 0.0, 0.0, 0.0};
  options.offsets[2] = ToolOffset{1.5, -2.0, 0.4, 8, 0.02, 0.0, 0.0};
  if (input.choice(2) == 0) options.machine.travel = TravelLimits{-10.0, 300.0, -200.0, 250.0};
  // The limits hold at any figure; small ones keep runs fast (the defaults let an endless
  // macro loop run a million blocks, 15 s under the sanitizers).
  options.maxMoves = 20000;
  options.maxSteps = 20000;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput input(data, size);
  const InterpreterOptions options = optionsFrom(input);
  const std::string_view text = input.rest();
  const InterpretResult result = interpret(text, "fuzz.nc", options);
  for (const Diagnostic& d : result.diagnostics) format(d);
  if (!result.ok()) return 0;
  cycleTimeS(result.toolpath);
  std::ostringstream csv;
  writeToolpathCsv(result.toolpath, csv);
  return 0;
}
