#include "interp/macro/functions.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

#include <fmt/format.h>

namespace lathesim::interp::macro {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
constexpr double kMaxWholeOperand = 9007199254740992.0;  // 2^53: every whole number below is exact

Error problem(std::string message) { return Error{0, 0, std::move(message)}; }

// The angle in [0, 360).
double normalizedDegrees(double degrees) {
  const double r = std::fmod(degrees, 360.0);
  return r < 0 ? r + 360.0 : r;
}

double sinDegrees(double degrees) {
  const double r = normalizedDegrees(degrees);
  if (r == 0.0 || r == 180.0) return 0.0;
  if (r == 90.0) return 1.0;
  if (r == 270.0) return -1.0;
  return std::sin(r * kRadiansPerDegree);
}

double cosDegrees(double degrees) { return sinDegrees(degrees + 90.0); }

// NAT = 0: an angle below 0 is given as the same angle + 360°.
double positiveDegrees(double radians) {
  const double degrees = radians / kRadiansPerDegree;
  return degrees < 0 ? degrees + 360.0 : degrees;
}

bool isWhole(double value) { return std::floor(value) == value; }

Result<std::uint64_t> bitwiseOperand(double value, std::string_view op) {
  if (value < 0 || !isWhole(value) || value >= kMaxWholeOperand) {
    return problem(fmt::format("{} works bit by bit on whole numbers ≥ 0; got {:g}", op, value));
  }
  return static_cast<std::uint64_t>(value);
}

Result<double> checkedRange(double value) {
  if (!std::isfinite(value) || std::abs(value) > kMaxMagnitude) {
    return problem("the result is out of the range a macro variable holds (±1e47; alarm 111)");
  }
  return value;
}

}  // namespace

double roundToIncrement(double value, double increment) { return std::round(value / increment) * increment; }

Result<double> applyFunction(Function function, const std::vector<double>& arguments,
                             std::optional<double> addressIncrement) {
  const double x = arguments.front();
  switch (function) {
    case Function::Sin: return sinDegrees(x);
    case Function::Cos: return cosDegrees(x);
    case Function::Tan: {
      const double c = cosDegrees(x);
      if (c == 0.0) return problem(fmt::format("TAN[{:g}] is infinite: the cosine of {:g}° is 0", x, x));
      return checkedRange(sinDegrees(x) / c);
    }
    case Function::Asin:
      if (x < -1.0 || x > 1.0) return problem(fmt::format("ASIN[{:g}]: the argument must lie in -1 to 1 (alarm 119)", x));
      return positiveDegrees(std::asin(x));
    case Function::Acos:
      if (x < -1.0 || x > 1.0) return problem(fmt::format("ACOS[{:g}]: the argument must lie in -1 to 1 (alarm 119)", x));
      return std::acos(x) / kRadiansPerDegree;
    case Function::Atan:
      if (arguments.size() == 1) return positiveDegrees(std::atan(x));
      if (x == 0.0 && arguments[1] == 0.0) return problem("ATAN[0]/[0] has no angle: both sides are 0 (alarm 119)");
      return positiveDegrees(std::atan2(x, arguments[1]));
    case Function::Sqrt:
      if (x < 0) return problem(fmt::format("SQRT[{:g}]: the square root of a negative number (alarm 119)", x));
      return std::sqrt(x);
    case Function::Abs: return std::abs(x);
    case Function::Round: return roundToIncrement(x, addressIncrement.value_or(1.0));
    case Function::Fix: return std::trunc(x);
    case Function::Fup: return x < 0 ? std::floor(x) : std::ceil(x);
    case Function::Ln:
      if (x <= 0) return problem(fmt::format("LN[{:g}]: the logarithm of a number ≤ 0 (alarm 119)", x));
      return std::log(x);
    case Function::Exp: return checkedRange(std::exp(x));
    case Function::Pow: {
      const double exponent = arguments[1];
      if (x < 0 && !isWhole(exponent)) {
        return problem(fmt::format("POW[{:g},{:g}]: a negative base needs a whole exponent (alarm 119)", x, exponent));
      }
      if (x == 0 && exponent <= 0) {
        return problem(fmt::format("POW[0,{:g}]: 0 needs a positive exponent (alarm 119)", exponent));
      }
      return checkedRange(std::pow(x, exponent));
    }
  }
  return problem("unknown function");
}

Result<double> applyBinary(BinaryOp op, double a, double b) {
  switch (op) {
    case BinaryOp::Add: return checkedRange(a + b);
    case BinaryOp::Subtract: return checkedRange(a - b);
    case BinaryOp::Multiply: return checkedRange(a * b);
    case BinaryOp::Divide:
      if (b == 0.0) return problem(fmt::format("division by zero: {:g} / 0 (alarm 112)", a));
      return checkedRange(a / b);
    case BinaryOp::Mod:
      if (!isWhole(a) || !isWhole(b)) {
        return problem(fmt::format("MOD takes whole numbers; got {:g} MOD {:g}", a, b));
      }
      if (b == 0.0) return problem(fmt::format("division by zero: {:g} MOD 0 (alarm 112)", a));
      return std::fmod(a, b);
    case BinaryOp::And:
    case BinaryOp::Or:
    case BinaryOp::Xor: {
      const std::string_view name = op == BinaryOp::And ? "AND" : op == BinaryOp::Or ? "OR" : "XOR";
      auto x = bitwiseOperand(a, name);
      if (!x.ok()) return x.error();
      auto y = bitwiseOperand(b, name);
      if (!y.ok()) return y.error();
      const std::uint64_t bits = op == BinaryOp::And  ? (x.value() & y.value())
                                 : op == BinaryOp::Or ? (x.value() | y.value())
                                                      : (x.value() ^ y.value());
      return static_cast<double>(bits);
    }
  }
  return problem("unknown operator");
}

}  // namespace lathesim::interp::macro
