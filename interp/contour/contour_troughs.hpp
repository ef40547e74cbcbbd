#pragma once
// The troughs of a G71/G72 contour (the Haas operator's manual, "Troughs": "a change in direction
// which creates a concave surface in the material being cut"), found in G71's axes: X the step
// axis, Z the cutting axis (G72 mirrors the contour first, as its engine does).

#include <cstddef>
#include <vector>

#include "interp/contour/contour.hpp"

namespace lathesim::interp {

/// The bottoms of the troughs of the blocks after the ns block, in contour order: each place
/// where the contour, having moved deeper (X the way `stepDir` points, +1 or −1), turns back
/// toward the start point's side; flats between the two count as the same bottom. For each,
/// the index in `contour` of the block that reaches the bottom (an arc whose X turns inside it
/// is its own bottom).
std::vector<std::size_t> troughBottoms(const Contour& contour, double stepDir);

}  // namespace lathesim::interp
