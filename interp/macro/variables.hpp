#pragma once
// The variables of Fanuc Custom Macro B (Fanuc 0i/16i "Custom macro: variables"):
//   #0            always <vacant>; it cannot be written
//   #1–#33        local: each macro call (G65) gets a fresh set, all <vacant> but its arguments;
//                 M99 gives the caller's set back. The main program is level 0; levels 0–4.
//   #100–#199     common, <vacant> at power on
//   #500–#999     common, kept through power off on a machine; <vacant> when a run starts
//                 unless the setup gives them
//   #1000 and up  system variables: the program writes #3000 (alarm) and #3006 (stop with a
//                 message), which the statements act on (macro/statement_runner.hpp); no other
//                 is simulated.
// A value is a real number or <vacant> (no value; not 0).

#include <array>
#include <map>
#include <optional>
#include <vector>

#include "interp/base/result.hpp"

namespace lathesim::interp::macro {

/// A macro variable's value: a number, or <vacant> (std::nullopt).
using Value = std::optional<double>;

constexpr int kLocalCount = 33;  // #1–#33
using LocalVariables = std::array<Value, kLocalCount>;

/// The system variables a program writes to stop.
constexpr int kAlarmVariable = 3000;  // #3000 = n (MESSAGE): alarm 3000 + n
constexpr int kStopVariable = 3006;   // #3006 = n (MESSAGE): stop; cycle start goes on

class VariableStore {
 public:
  /// `commonValues`: values of common variables given before the run (#100–#199, #500–#999).
  explicit VariableStore(const std::map<int, double>& commonValues = {});

  /// The value of #`number`; fails (located at `line`:`column`) for a number that is no variable.
  Result<Value> read(int number, int line, int column) const;
  /// Sets #`number`; fails for #0, for system variables and for numbers that are no variable.
  Status write(int number, Value value, int line, int column);

  /// A macro call's fresh local variables (its arguments set, the rest <vacant>).
  void pushLevel(const LocalVariables& arguments) { locals_.push_back(arguments); }
  /// Back to the caller's local variables (M99 from a macro).
  void popLevel() { locals_.pop_back(); }
  int level() const { return static_cast<int>(locals_.size()) - 1; }

  /// Whether #`number` is a common variable (#100–#199, #500–#999).
  static bool isCommon(int number);

 private:
  Status noSuchVariable(int number, int line, int column) const;

  std::vector<LocalVariables> locals_;  // level 0 (the main program) first
  std::array<Value, 100> common100_{};  // #100–#199
  std::array<Value, 500> common500_{};  // #500–#999
};

}  // namespace lathesim::interp::macro
