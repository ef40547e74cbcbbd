#pragma once
// The words each dialect's thread codes take besides the axes and F (lathe-cycles.md §1, §2,
// §6; GSK980TDi 3.24.1, 3.24.9, 3.24.12; HNC-18iT programming manual §9.1.3 (G82)).

#include "interp/control/dialect.hpp"

namespace lathesim::interp {

struct ThreadingWords {
  bool threadsPerInchI = false;  // GSK: I = threads per inch, the lead 25.4/I mm (G32, G92, G76)
  bool runoutJK = false;         // GSK: J (short axis) and K (long axis) run-out (G32, G92, G76)
  bool startsL = false;          // GSK: G92 L = number of starts
  bool hncRunoutRE = false;      // HNC G82: R (Z) and E (X, a radius) run-out
  bool hncStartsCP = false;      // HNC G82: C = number of starts, P = the first start's angle (°)
  bool fanucToolAngles = false;  // G76 a is one of 80, 60, 55, 30, 29, 0 (Fanuc), not 0–99 (GSK)
};

inline ThreadingWords threadingWords(Dialect dialect) {
  switch (dialect) {
    case Dialect::FanucA: return {true, true, true, false, false, false};  // GSK980TDi
    case Dialect::FanucB: return {false, false, false, false, false, true};
    case Dialect::Hnc: return {false, false, false, true, true, false};
    case Dialect::Haas: return {false, false, false, false, false, false};  // G76 A: 0–120° (Haas)
  }
  return {};
}

}  // namespace lathesim::interp
