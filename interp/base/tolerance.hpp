#pragma once
// The length below which the interpreter treats two positions as one (a contour's closing
// point, a leg of zero length, a corner with no turn): far below any voxel or control
// increment, above the rounding of a few additions of millimetre values.

namespace lathesim::interp {

inline constexpr double kTolMm = 1e-9;

}  // namespace lathesim::interp
