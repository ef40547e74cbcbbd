#pragma once
// Where a programmed number becomes millimetres: the one place for G20 (inch) and for the
// control's decimal point parameters (control_parameters.hpp).
//   a length written with a decimal point       X20.  = 20 mm (20 inch under G20)
//   a length written without one, "calculator"   X20   = 20 mm, as the GSK980TDi reads it
//   a length written without one, "increments"   X20   = 20 least increments = 0.020 mm at
//                                                IS-B (0.002 inch), as a Fanuc with DPI = 0
//   a [LII] word (G74/G75/G76 P, Q, R(Δd))       P1500 = 1.5 mm at IS-B whatever the input
//                                                mode; with a point it is a length (P1.5)
// The least increment is 0.001 mm (IS-B) or 0.0001 mm (IS-C); in inch a tenth of that in
// inches (0.0001 / 0.00001 inch).

#include <string>

#include "interp/control/control_parameters.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {

constexpr double kMmPerInch = 25.4;

/// How the control reads the numbers of lengths: the unit in force and its parameters.
struct NumberReading {
  bool inch = false;  // G20
  DecimalPointInput decimalPointInput = DecimalPointInput::Calculator;
  IncrementWordInput incrementWordInput = IncrementWordInput::LeastIncrements;
  double leastIncrementMm = 0.001;

  static NumberReading of(const ControlParameters& control, bool inch) {
    return {inch, control.decimalPointInput, control.incrementWordInput, control.leastIncrementMm};
  }
  /// One least increment in the unit in force (mm, or inch under G20).
  double leastIncrement() const { return inch ? leastIncrementMm / 10.0 : leastIncrementMm; }
  /// A value in the unit in force, in mm.
  double mm(double value) const { return inch ? value * kMmPerInch : value; }
};

inline bool hasDecimalPoint(const Word& word) { return word.number.find('.') != std::string::npos; }

/// A length word (X, Z, U, W, I, K, R, a cycle's depth or allowance) in mm.
inline double lengthMm(const Word& word, const NumberReading& reading) {
  if (hasDecimalPoint(word) || reading.decimalPointInput == DecimalPointInput::Calculator)
    return reading.mm(word.value);
  return reading.mm(word.value * reading.leastIncrement());
}

/// A word of the kind lathe-cycles.md marks [LII] (G74/G75 P, Q and R(Δd)) in mm: without a
/// decimal point it counts least input increments (P1500 = 1.5 mm at IS-B), unless the
/// control reads those words in mm (GSK No.182#7); with a point it is a length as written.
inline double incrementLengthMm(const Word& word, const NumberReading& reading) {
  if (hasDecimalPoint(word) || reading.incrementWordInput == IncrementWordInput::Calculator)
    return reading.mm(word.value);
  return reading.mm(word.value * reading.leastIncrement());
}

/// A time word of G04 (X or U) in seconds: without a decimal point a control that counts
/// least increments reads it in increments of the same size in seconds (X1500 = 1.5 s at IS-B).
inline double dwellSeconds(const Word& word, const NumberReading& reading) {
  if (hasDecimalPoint(word) || reading.decimalPointInput == DecimalPointInput::Calculator) return word.value;
  return word.value * reading.leastIncrementMm;
}

}  // namespace lathesim::interp
