#pragma once
// The meridian section of a triangle mesh of a turned part: where its surface crosses the
// half-plane y = 0, x ≥ 0, as segments of (r = x, z). For a mesh made by revolving a
// profile (an STL of the design), that is the profile: exactly, where the mesh has vertices
// in that plane, and otherwise its chords, within r·(1 − cos(π/n)) for n facets around.

#include <vector>

#include "geometry/meridian_profile.hpp"
#include "geometry/triangle_mesh.hpp"

namespace lathesim {

std::vector<Segment> meridianSlice(const TriangleMesh& mesh);

}  // namespace lathesim
