#pragma once
// The plain triangle mesh that travels from sim (which owns OpenVDB) to render (which owns
// VTK), so neither library leaks into the other.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lathesim {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;                // mm, part coordinates (Z = spindle axis)
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

/// Enclosed volume by the divergence theorem (mm³); exact for a closed, consistently
/// oriented mesh, and positive when the normals point outwards.
double enclosedVolumeMm3(const TriangleMesh& mesh);

/// Surface area (mm²).
double surfaceAreaMm2(const TriangleMesh& mesh);

/// True when every edge is shared by exactly two triangles that traverse it in opposite
/// directions: the mesh is closed, manifold along its edges and consistently oriented.
bool isClosedAndOriented(const TriangleMesh& mesh);

/// Makes vertices at the same position one vertex, as a reader of an STL file (which
/// stores each triangle's corners, not shared vertices) does. After it, isClosedAndOriented
/// tells whether the STL written from the mesh is closed and manifold (a triangle with two
/// corners at one point is not).
void weldCoincidentVertices(TriangleMesh& mesh);

/// Drops the triangles with two corners at one vertex (no area); returns how many.
std::size_t dropCollapsedTriangles(TriangleMesh& mesh);

}  // namespace lathesim
