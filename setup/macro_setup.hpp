#pragma once
// The setup file's [macro] table: what Custom Macro B programs find when they start.
//   [macro]
//   max_steps = 1000000         # blocks the program may run again (a block's first run is
//                               # free); an endless loop stops there with an error naming it
//   variables = { 500 = 20.0 }  # common variables the control holds before the run
//                               # (#100–#199, #500–#999; #500 up survive power off on a
//                               # machine, so part-family programs often read them)
// Both keys are optional; --max-steps overrides max_steps.

#include <map>

#include <toml++/toml.h>

#include "interp/state/step_guard.hpp"
#include "setup/offset_setup.hpp"  // ReportProblem

namespace lathesim::setup {

struct MacroSetup {
  long long maxSteps = interp::kDefaultMaxSteps;
  std::map<int, double> variables;  // variable number → value
};

/// Reads the `macro` key's value (a table) into `macro`; every problem (a wrong type, an
/// unknown key, a step limit below 1, a variable that is not common) is reported naming the key.
void readMacroSetup(const toml::node& node, MacroSetup& macro, const ReportProblem& report);

}  // namespace lathesim::setup
