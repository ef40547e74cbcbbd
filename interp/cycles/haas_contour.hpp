#pragma once
// The Haas rule on where a G71/G72 contour may go (the Haas operator's manual, "Type 2 details"):
// the PQ path must not pass the start point in the step axis, the Q block excepted (a short
// retraction at the end of the contour is allowed and roughed as any block). Troughs, in type I
// as in type II, are roughed by the engine (stock_removal.cpp, RoughingParams::haasTroughs).

#include <optional>

#include "geometry/rz.hpp"
#include "interp/contour/contour.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// The block of a Haas G71 (`turning`) or G72 contour run from `start` that passes the start
/// point before the Q block, as an Error, or nullopt.
std::optional<Error> haasContourProblem(const RZ& start, const Contour& contour, bool turning);

}  // namespace lathesim::interp
