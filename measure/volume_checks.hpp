#pragma once
// Whether the volumes a run reports can be trusted: each is checked against a figure found
// another way, within sim::volumeToleranceMm3 (5 % of a voxel layer over the surface).

#include <optional>
#include <string>
#include <string_view>

#include "geometry/mesh_shells.hpp"
#include "geometry/triangle_mesh.hpp"
#include "sim/stock_spec.hpp"

namespace lathesim::measure {

/// Why the untouched bar's level-set volume is not its exact π(R² − r²)L (r the bore's
/// radius, 0 for a solid bar) within the tolerance over the bar's surface, or nullopt.
std::optional<std::string> barVolumeProblem(const sim::StockSpec& bar, double levelSetMm3, double voxelMm);

/// Why the part's level-set volume and the volume enclosed by its mesh (all of it, crumbs
/// included) disagree by more than the tolerance over the mesh's surface, or nullopt.
/// `solid` names it: "part", or "stub" (the stock left in the chuck after a part-off).
std::optional<std::string> meshVolumeProblem(double levelSetMm3, const TriangleMesh& mesh, double voxelMm,
                                             std::string_view solid = "part");

/// Why the mesh would not make a closed, manifold STL (some edge not shared by exactly two
/// triangles), or nullopt; `solid` as above, and its STL is solid.stl.
std::optional<std::string> meshClosureProblem(const TriangleMesh& mesh, std::string_view solid = "part");

/// What a run checks on a solid's fresh mesh, and the mesh it keeps.
struct MeshCheck {
  std::optional<std::string> volumeProblem;   // meshVolumeProblem on the whole mesh, crumbs included
  DroppedCrumbs crumbs;                       // what dropCrumbs(mesh, voxelMm) took out
  std::optional<std::string> closureProblem;  // meshClosureProblem on what is kept
  double volumeMm3 = 0;                       // enclosed by what is kept (enclosedVolumeMm3)
  double areaMm2 = 0;                         // its surface (surfaceAreaMm2)
};

/// meshVolumeProblem, dropCrumbs(mesh, voxelMm), meshClosureProblem and the kept mesh's
/// volume and area, to the last bit as those give them, with each triangle's volume and area
/// terms computed once (in parallel) rather than by four serial passes.
MeshCheck checkMesh(TriangleMesh& mesh, double levelSetMm3, double voxelMm, std::string_view solid = "part");

}  // namespace lathesim::measure
