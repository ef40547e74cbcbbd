#pragma once
// Two G71/G72 contours a Haas treats in its own way (lathesim reads Haas's one-block G71/G72 by
// Fanuc's rules otherwise): a contour whose last block retracts past the start point (the
// manual asks for one after a last cut that is not monotonic, but gives no rule for the
// roughing), and a type I contour with a pocket (the manual's "Troughs": the material above
// every trough first, then the troughs along Z — not simulated yet). Each is refused at its
// block rather than cut by a guess.

#include <optional>

#include "geometry/rz.hpp"
#include "interp/cycles/contour.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// Why a Haas G71 (`turning`) or G72 contour run from `start` is not simulated, or nullopt.
/// `typeII`: the P block moves both axes.
std::optional<Error> haasContourProblem(const RZ& start, const Contour& contour, bool turning, bool typeII);

}  // namespace lathesim::interp
