#pragma once
// The work coordinate systems G54–G59 (GSK980TDi 3.21, Fanuc 0i-T): each is a shift of the
// program's zero in the setup's frame (where the stock, the start and the reference point are
// given); an external work offset is added to all six. The interpreter works in the selected
// system's coordinates; every move carries the shift in force and is placed in the setup's
// frame once the program has run (interpreter.cpp). Selecting another system does not move
// the tool: its coordinates change by the difference of the two shifts, as on the control
// ("new absolute = current absolute − (ZOFS new − ZOFS old)"), so the shift applies to every
// programmed coordinate from the next move on.

#include <array>

#include "geometry/rz.hpp"

namespace lathesim::interp {

/// The external work offset (index 0, G10 L2 P0) and G54…G59 (indices 1…6), each
/// (radius mm, Z mm) in the setup's frame. All zero unless the setup or G10 L2 says otherwise.
using WorkOffsets = std::array<RZ, 7>;

inline WorkOffsets zeroWorkOffsets() {
  WorkOffsets offsets;
  offsets.fill(RZ(0, 0));
  return offsets;
}

struct WorkFrame {
  WorkOffsets offsets = zeroWorkOffsets();
  int system = 1;  // 1…6 for G54…G59; G54 at power-on
  // G50 X(U) Z(W) (GSK980TDi §3.18) declares the tool's coordinates: the frame moves by the
  // difference, whatever system is selected (all six move together, as on a Fanuc's G92).
  RZ coordinateSetting{0, 0};

  /// Where program zero lies in the setup's frame: external + the selected system's offset +
  /// G50's shift.
  RZ shift() const { return offsets[0] + offsets[static_cast<std::size_t>(system)] + coordinateSetting; }
};

}  // namespace lathesim::interp
