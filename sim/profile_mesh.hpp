#pragma once
// Inside sim only: the mesh of a stock that is still a solid of revolution, drawn from its
// profile in the revolved table rather than from its level set (see profile_mesh.cpp).

#include <optional>

#include "geometry/triangle_mesh.hpp"
#include "sim/revolved_table.hpp"

namespace lathesim::sim {

/// How far the simplified profile may stray from the table's zero crossing: a hundredth of a
/// voxel (see profile_mesh.cpp).
inline constexpr double kProfileToleranceVoxels = 0.01;
/// How far a chord of the revolution may stray from the circle at the profile's largest
/// radius, before the radii are widened to give the true volume: a twentieth of a voxel.
inline constexpr double kChordToleranceVoxels = 0.05;

/// How the profile is kept: simplified (the fewest points within kProfileToleranceVoxels), or
/// every crossing (about a point a voxel along the profile), for a mesh whose vertices carry
/// values that vary along a straight face, as deviation.png's colours do.
enum class ProfilePoints { Simplified, EveryCrossing };

/// The surface where the table's values cross `isoMm` (Stock::mesh's level, a hair inside
/// φ = 0), revolved about Z: closed, normals out of the material, each point on the axis one
/// vertex. Its enclosed volume is the Pappus volume of the (simplified) profile. nullopt when
/// the crossing does not close inside the table (material at its edge: never for a stock
/// the table holds), so that the caller meshes the level set instead.
std::optional<TriangleMesh> profileMesh(const RevolvedTable& table, double voxelMm, double isoMm,
                                        ProfilePoints points = ProfilePoints::Simplified);

}  // namespace lathesim::sim
