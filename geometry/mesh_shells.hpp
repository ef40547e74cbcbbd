#pragma once
// The separate pieces (shells) of a closed triangle mesh, and dropping the crumbs among them.

#include <cstddef>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace lathesim {

struct Shell {
  std::vector<std::size_t> triangles;  // indices into the mesh's triangles
  double volumeMm3 = 0;                // enclosed (divergence theorem)
  double areaMm2 = 0;
};

/// The mesh's connected pieces: triangles that share a vertex belong to one shell.
std::vector<Shell> shellsOf(const TriangleMesh& mesh);

struct DroppedCrumbs {
  std::size_t count = 0;
  double volumeMm3 = 0;  // what they enclosed
};

/// Removes the shells, other than the largest, thinner on average than `thicknessMm` —
/// twice their volume over their area, which is a sheet's thickness (a ring of square
/// section s gives s/2) — and returns what they enclosed. A level set cannot hold a
/// feature thinner than its voxel: what comes out of one is a scatter of loose crumbs.
DroppedCrumbs dropCrumbs(TriangleMesh& mesh, double thicknessMm);

}  // namespace lathesim
