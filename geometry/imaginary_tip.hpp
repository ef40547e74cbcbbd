#pragma once
// The imaginary tool tip numbers of Fanuc lathes (../shared/spec/lathe-cycles.md §8): tip T
// says in which direction the programmed point P lies from the nose-radius centre C,
// P = C + R·s(T), s in axis terms (radial, axial):
//            +X
//       2    6    1
//  -Z   7   0/9   5   +Z
//       3    8    4
//            -X
// 3 is the usual OD turning tool; 0 and 9 make the programmed point the centre itself.

#include "geometry/rz.hpp"

namespace lathesim {

/// (sX, sZ) of a tip number 0–9; (0, 0) for 0, 9 and anything else.
inline RZ imaginaryTipDirection(int tipNumber) {
  switch (tipNumber) {
    case 1: return RZ(1, 1);
    case 2: return RZ(1, -1);
    case 3: return RZ(-1, -1);
    case 4: return RZ(-1, 1);
    case 5: return RZ(0, 1);
    case 6: return RZ(1, 0);
    case 7: return RZ(0, -1);
    case 8: return RZ(-1, 0);
    default: return RZ(0, 0);
  }
}

}  // namespace lathesim
