#pragma once
// What the cycles expand into: legs, before the interpreter stamps tool, feed and source on
// them.

#include <initializer_list>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

/// One leg of a canned cycle. Positions are (radius mm, Z mm).
struct CycleLeg {
  MoveKind kind = MoveKind::Rapid;
  RZ from{0, 0};
  RZ to{0, 0};
  int step = 0;       // the cycle's own step number (1–4 for G90/G94); 0 when it has none
  RZ center{0, 0};    // arcs only
  ThreadMotion thread{};  // Thread legs only
};

/// The legs in order, the zero-length ones left out.
inline std::vector<CycleLeg> keptLegs(std::initializer_list<CycleLeg> legs) {
  std::vector<CycleLeg> kept;
  for (const CycleLeg& leg : legs) {
    if (leg.from != leg.to) kept.push_back(leg);
  }
  return kept;
}

}  // namespace lathesim::interp
