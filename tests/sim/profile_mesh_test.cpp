// The mesh of a revolved stock drawn from its profile (sim/profile_mesh.cpp), on profiles whose
// volume is worked out by hand (Pappus: cylinders and a cone): a stepped shaft, a cone to the
// axis, a face-turned end, a tube with a counterbore, a tube grooved through into a ring and a
// bar cut in two. Each at 0.1, 0.13 and 0.2 mm voxels, its dimensions shifted off the voxel
// grid by fractions of a voxel. The mesh must be closed and consistently wound (also as an
// STL reader glues it), its volume the exact one, its vertices on the level set's surface,
// one vertex per point on the axis, and it must agree with the level set's own mesh in volume
// and extent.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "sim/profile_mesh.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadiusMm = 10.0;  // every case starts from a Φ20 × 20 bar (or tube), face at Z0
constexpr double kLengthMm = 20.0;
constexpr double kBeyondMm = 2.0;   // how far a cut reaches past the bar

RevolvedRegion box(double rhoLow, double rhoHigh, double zLow, double zHigh) {
  const std::vector<RZ> corners{{rhoLow, zLow}, {rhoHigh, zLow}, {rhoHigh, zHigh}, {rhoLow, zHigh}};
  return RevolvedRegion({ConvexPolygon::hullOf(corners)});
}
double cylinderMm3(double rOuter, double rInner, double length) { return kPi * (rOuter * rOuter - rInner * rInner) * length; }

struct Profile {
  double boreMm = 0;                   // the bar's bore (diameter)
  std::vector<RevolvedRegion> cuts;    // removed in turn
  double volumeMm3 = 0;                // by hand
  double areaMm2 = 0;                  // by hand, for the tolerance
  int shells = 1;
  std::vector<RZ> corners;             // where the profile turns, off the axis
  double topZMm = 0;                   // the material's highest Z (the bar's face unless cut)
};

// The cases, with every dimension moved by `s` (mm): off the voxel grid, and by different
// fractions of a voxel at each voxel size.
struct ProfileMeshCase {
  const char* name;
  std::function<Profile(double s)> make;
};

const std::vector<ProfileMeshCase>& cases() {
  static const std::vector<ProfileMeshCase> all{
      {"stepped shaft",
       [](double s) {
         const double r1 = 7.37 + s, a = 12.3 + s, r2 = 4.11 + s, b = 5.53 + s;
         Profile p;
         p.cuts = {box(r1, kRadiusMm + kBeyondMm, -a, kBeyondMm), box(r2, kRadiusMm + kBeyondMm, -b, kBeyondMm)};
         p.volumeMm3 = cylinderMm3(kRadiusMm, 0, kLengthMm) - cylinderMm3(kRadiusMm, r1, a) - cylinderMm3(r1, r2, b);
         p.areaMm2 = 2 * kPi * (kRadiusMm * (kLengthMm - a) + r1 * (a - b) + r2 * b) + 2 * kPi * kRadiusMm * kRadiusMm;
         p.corners = {{kRadiusMm, -kLengthMm}, {kRadiusMm, -a}, {r1, -a}, {r1, -b}, {r2, -b}, {r2, 0}};
         return p;
       }},
      {"cone to the axis",
       [](double s) {
         // Material ρ ≤ R·(−z)/H for −H ≤ z ≤ 0: the cut is everything above that line, drawn
         // across the axis so that the axis is no edge of it.
         const double h = 8.61 + s, slope = h / kRadiusMm, far = kRadiusMm + kBeyondMm;
         const std::vector<RZ> above{{-1.0, slope}, {far, -slope * far}, {far, kBeyondMm}, {-1.0, kBeyondMm}};
         Profile p;
         p.cuts = {RevolvedRegion({ConvexPolygon::hullOf(above)})};
         p.volumeMm3 = cylinderMm3(kRadiusMm, 0, kLengthMm - h) + kPi * kRadiusMm * kRadiusMm * h / 3.0;
         p.areaMm2 = 2 * kPi * kRadiusMm * (kLengthMm - h) + kPi * kRadiusMm * std::hypot(kRadiusMm, h) +
                     kPi * kRadiusMm * kRadiusMm;
         p.corners = {{kRadiusMm, -kLengthMm}, {kRadiusMm, -h}};
         return p;
       }},
      {"face-turned end",
       [](double s) {
         const double f = 1.29 + s;
         Profile p;
         p.cuts = {box(-kRadiusMm - kBeyondMm, kRadiusMm + kBeyondMm, -f, kBeyondMm)};
         p.volumeMm3 = cylinderMm3(kRadiusMm, 0, kLengthMm - f);
         p.areaMm2 = 2 * kPi * kRadiusMm * (kLengthMm - f) + 2 * kPi * kRadiusMm * kRadiusMm;
         p.corners = {{kRadiusMm, -kLengthMm}, {kRadiusMm, -f}};
         p.topZMm = -f;
         return p;
       }},
      {"tube with a counterbore and a step",
       [](double s) {
         const double bore = 3.0, counterbore = 5.17 + s, depth = 6.41 + s, r1 = 8.23 + s, a = 9.07 + s;
         Profile p;
         p.boreMm = 2 * bore;
         p.cuts = {box(-counterbore, counterbore, -depth, kBeyondMm), box(r1, kRadiusMm + kBeyondMm, -a, kBeyondMm)};
         p.volumeMm3 = cylinderMm3(kRadiusMm, bore, kLengthMm) - cylinderMm3(counterbore, bore, depth) -
                       cylinderMm3(kRadiusMm, r1, a);
         p.areaMm2 = 2 * kPi * (kRadiusMm + bore) * kLengthMm + 2 * kPi * kRadiusMm * kRadiusMm;
         p.corners = {{kRadiusMm, -kLengthMm}, {bore, -kLengthMm}, {kRadiusMm, -a}, {r1, -a},
                      {r1, 0}, {counterbore, 0}, {counterbore, -depth}, {bore, -depth}};
         return p;
       }},
      {"tube grooved through into a ring",
       [](double s) {
         const double bore = 4.0, z0 = -11.43 - s, width = 2.71 + s;
         Profile p;
         p.boreMm = 2 * bore;
         p.cuts = {box(bore - 1.0, kRadiusMm + kBeyondMm, z0, z0 + width)};
         p.volumeMm3 = cylinderMm3(kRadiusMm, bore, kLengthMm - width);
         p.areaMm2 = 2 * kPi * (kRadiusMm + bore) * kLengthMm + 4 * kPi * kRadiusMm * kRadiusMm;
         for (const double z : {-kLengthMm, z0, z0 + width, 0.0}) p.corners.insert(p.corners.end(), {{kRadiusMm, z}, {bore, z}});
         p.shells = 2;
         return p;
       }},
      {"bar cut in two",
       [](double s) {
         const double z0 = -9.17 + s, width = 1.93 + s;
         Profile p;
         p.cuts = {box(-kRadiusMm - kBeyondMm, kRadiusMm + kBeyondMm, z0, z0 + width)};
         p.volumeMm3 = cylinderMm3(kRadiusMm, 0, kLengthMm - width);
         p.areaMm2 = 2 * kPi * kRadiusMm * kLengthMm + 4 * kPi * kRadiusMm * kRadiusMm;
         p.corners = {{kRadiusMm, -kLengthMm}, {kRadiusMm, z0}, {kRadiusMm, z0 + width}, {kRadiusMm, 0}};
         p.shells = 2;
         return p;
       }},
  };
  return all;
}

StockSpec barOf(const Profile& p) {
  StockSpec bar;
  bar.diameterMm = 2 * kRadiusMm;
  bar.lengthMm = kLengthMm;
  bar.faceZMm = 0.0;
  bar.boreMm = p.boreMm;
  return bar;
}

// Each vertex's ring (x, y) → radius and the faces around; the shells by connectivity.
int shellCount(const TriangleMesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.vertices.size());
  for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
  const std::function<std::uint32_t(std::uint32_t)> root = [&](std::uint32_t v) {
    return parent[v] == v ? v : parent[v] = root(parent[v]);
  };
  for (const auto& t : mesh.triangles) {
    parent[root(t[1])] = root(t[0]);
    parent[root(t[2])] = root(t[0]);
  }
  std::set<std::uint32_t> roots;
  for (const auto& t : mesh.triangles) roots.insert(root(t[0]));
  return static_cast<int>(roots.size());
}

struct Box {
  Eigen::Vector3f low{1e9f, 1e9f, 1e9f}, high{-1e9f, -1e9f, -1e9f};
};
Box boxOf(const TriangleMesh& mesh) {
  Box b;
  for (const auto& v : mesh.vertices) b.low = b.low.cwiseMin(v), b.high = b.high.cwiseMax(v);
  return b;
}

class ProfileMesh : public ::testing::TestWithParam<double> {};

TEST_P(ProfileMesh, IsClosedExactAndOnTheLevelSet) {
  const double h = GetParam();
  // Shifts of 0 and of odd fractions of this voxel: dimensions on and off voxel centres.
  for (const double shift : {0.0, 0.37 * h}) {
    for (const ProfileMeshCase& c : cases()) {
      SCOPED_TRACE(std::string(c.name) + " at " + std::to_string(h) + " mm voxels, shifted " + std::to_string(shift) + " mm");
      const Profile p = c.make(shift);
      Stock stock(barOf(p), h);
      for (const RevolvedRegion& cut : p.cuts) stock.remove(cut);
      ASSERT_TRUE(stock.isRevolved());
      const TriangleMesh mesh = stock.mesh(0.0);
      ASSERT_FALSE(mesh.triangles.empty());

      EXPECT_TRUE(isClosedAndOriented(mesh));
      TriangleMesh asStl = mesh;  // as an STL reader glues it: nothing to glue
      weldCoincidentVertices(asStl);
      EXPECT_EQ(asStl.vertices.size(), mesh.vertices.size()) << "two vertices at one point";
      EXPECT_EQ(dropCollapsedTriangles(asStl), 0u);
      EXPECT_EQ(shellCount(mesh), p.shells);

      // Pappus on the profile: the revolution's chords are corrected for, and what is left is
      // the profile's simplification (h/100) and the level set's own placement of corners.
      const double volume = enclosedVolumeMm3(mesh);
      const double tolerance = volumeToleranceMm3(p.areaMm2, h);
      EXPECT_NEAR(volume, p.volumeMm3, 0.2 * tolerance);
      EXPECT_NEAR(volume, stock.volumeMm3(), tolerance);

      // Every vertex and every facet's middle on the level set's surface (the mesh's level):
      // within the chord's stray (⅔ of h/20 outwards at the vertices, ⅓ inwards between),
      // the profile's tolerance (h/100) and the sampling's rounding of a smooth surface. At a
      // corner the level set's trilinear sampling itself rounds the corner off (by up to 0.3 h
      // where the corner sits in a voxel's middle), which the profile does not.
      std::vector<Eigen::Vector3d> points;
      for (const auto& v : mesh.vertices) points.push_back(v.cast<double>());
      for (const auto& t : mesh.triangles)
        points.push_back((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]).cast<double>() / 3.0);
      std::vector<double> phi(points.size());
      stock.signedDistancesAt(points, phi);
      double worstOnFaces = 0, worstAtCorners = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const RZ meridian(std::hypot(points[i].x(), points[i].y()), points[i].z());
        const bool nearCorner = std::any_of(p.corners.begin(), p.corners.end(),
                                            [&](const RZ& corner) { return (corner - meridian).norm() < 1.5 * h; });
        double& worst = nearCorner ? worstAtCorners : worstOnFaces;
        worst = std::max(worst, std::abs(phi[i]));
      }
      EXPECT_LT(worstOnFaces, 0.05 * h);
      EXPECT_LT(worstAtCorners, 0.35 * h);

      // The angular step: no chord of a ring strays more than h/20 from its circle (a hair
      // more on the radii widened by √(θ/sin θ)).
      double worstSagitta = 0;
      for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e) {
          const Eigen::Vector3f a = mesh.vertices[t[e]], b = mesh.vertices[t[(e + 1) % 3]];
          const double ra = std::hypot(a.x(), a.y()), rb = std::hypot(b.x(), b.y());
          if (a.z() != b.z() || ra == 0 || std::abs(ra - rb) > 1e-5 * ra) continue;  // no chord of a ring
          worstSagitta = std::max(worstSagitta, ra - std::hypot(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y())));
        }
      EXPECT_LT(worstSagitta, 1.01 * kChordToleranceVoxels * h);
      EXPECT_GT(worstSagitta, 0.5 * kChordToleranceVoxels * h);  // and not many more chords than that needs

      // One vertex per point on the axis.
      std::set<float> axisZ;
      std::size_t onAxis = 0;
      for (const auto& v : mesh.vertices)
        if (v.x() == 0.0f && v.y() == 0.0f) ++onAxis, axisZ.insert(v.z());
      EXPECT_EQ(axisZ.size(), onAxis);
    }
  }
}

TEST_P(ProfileMesh, AgreesWithTheLevelSetsMesh) {
  const double h = GetParam();
  for (const ProfileMeshCase& c : cases()) {
    SCOPED_TRACE(std::string(c.name) + " at " + std::to_string(h) + " mm voxels");
    const Profile p = c.make(0.29 * h);
    Stock revolved(barOf(p), h), voxels(barOf(p), h, RevolvedWrites::Voxels);
    for (const RevolvedRegion& cut : p.cuts) revolved.remove(cut), voxels.remove(cut);
    ASSERT_TRUE(revolved.isRevolved());
    ASSERT_FALSE(voxels.isRevolved());
    const TriangleMesh fromProfile = revolved.mesh(0.0), fromLevelSet = voxels.mesh(0.0);
    EXPECT_NEAR(enclosedVolumeMm3(fromProfile), enclosedVolumeMm3(fromLevelSet), volumeToleranceMm3(p.areaMm2, h));
    EXPECT_LT(fromProfile.triangles.size(), fromLevelSet.triangles.size() / 10);
    // The profile's mesh spans the part's extent (its vertices at ±X and ±Y widened by ⅔ of
    // the chord's h/20); the level set's rounds a sharp tip off (the cone's, by most of a
    // voxel) and places the rest within a fraction of a voxel.
    const Box a = boxOf(fromProfile), b = boxOf(fromLevelSet);
    const Eigen::Vector3f exactLow(-kRadiusMm, -kRadiusMm, -kLengthMm), exactHigh(kRadiusMm, kRadiusMm, p.topZMm);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(a.low[axis], exactLow[axis], 0.05 * h) << "axis " << axis;
      EXPECT_NEAR(a.high[axis], exactHigh[axis], 0.05 * h) << "axis " << axis;
      EXPECT_NEAR(a.low[axis], b.low[axis], h) << "axis " << axis;
      EXPECT_NEAR(a.high[axis], b.high[axis], h) << "axis " << axis;
    }
  }
}

// The longest edge along the profile (between two rings, not a chord of one), in the meridian.
double longestProfileEdgeMm(const TriangleMesh& mesh) {
  double longest = 0;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3f a = mesh.vertices[t[e]], b = mesh.vertices[t[(e + 1) % 3]];
      const RZ ma(std::hypot(a.x(), a.y()), a.z()), mb(std::hypot(b.x(), b.y()), b.z());
      if (std::abs(ma.y() - mb.y()) < 1e-6 && std::abs(ma.x() - mb.x()) < 1e-5 * std::max(1.0, ma.x())) continue;
      // A ring-to-ring edge may run diagonally between two angles: its meridian length is what
      // the vertex values are blended over.
      longest = std::max(longest, (ma - mb).norm());
    }
  return longest;
}

// deviation.png colours a mesh vertex by vertex: its mesh has a point of the profile at least
// every voxel, where the part's own mesh is one band of facets along each straight face; and
// not many more (a face across the axis crosses a radius class every few thousandths of a mm).
TEST_P(ProfileMesh, MeshWithVertexEveryVoxelHasAPointEveryVoxel) {
  const double h = GetParam();
  for (const ProfileMeshCase& c : cases()) {
    SCOPED_TRACE(std::string(c.name) + " at " + std::to_string(h) + " mm voxels");
    const Profile p = c.make(0.41 * h);
    Stock stock(barOf(p), h);
    for (const RevolvedRegion& cut : p.cuts) stock.remove(cut);
    ASSERT_TRUE(stock.isRevolved());
    const TriangleMesh dense = stock.meshWithVertexEveryVoxel(), simplified = stock.mesh(0.0);
    EXPECT_TRUE(isClosedAndOriented(dense));
    EXPECT_EQ(shellCount(dense), p.shells);
    EXPECT_NEAR(enclosedVolumeMm3(dense), p.volumeMm3, 0.2 * volumeToleranceMm3(p.areaMm2, h));
    EXPECT_LT(longestProfileEdgeMm(dense), 1.01 * h);  // the radii widened by √(θ/sin θ)
    // The level set's mesh has a vertex every voxel of the surface; this one every voxel along
    // the profile times its rings' chords (a seventh of that here). Keeping every crossing
    // would come near it: ~2,000 points on the faces across the axis alone.
    Stock voxels(barOf(p), h, RevolvedWrites::Voxels);
    for (const RevolvedRegion& cut : p.cuts) voxels.remove(cut);
    EXPECT_LT(dense.vertices.size(), 0.3 * voxels.mesh(0.0).vertices.size());
    EXPECT_GT(longestProfileEdgeMm(simplified), 20 * h);  // every case has a straight face of 2 mm or more
  }
}

INSTANTIATE_TEST_SUITE_P(Voxels, ProfileMesh, ::testing::Values(0.1, 0.13, 0.2));

// The untouched bar: its cylinder, ends closed by fans on the axis.
TEST(ProfileMeshBar, IsTheBarsCylinder) {
  StockSpec bar;
  bar.diameterMm = 20;
  bar.lengthMm = 20;
  bar.faceZMm = 0;
  Stock stock(bar, 0.2);
  ASSERT_TRUE(stock.isRevolved());
  const TriangleMesh mesh = stock.mesh(0.0);
  EXPECT_TRUE(isClosedAndOriented(mesh));
  EXPECT_NEAR(enclosedVolumeMm3(mesh), cylinderMm3(10, 0, 20), 0.2 * volumeToleranceMm3(surfaceAreaMm2(bar), 0.2));
  // Two points on the axis (the end faces' centres) and two rings.
  EXPECT_EQ(mesh.vertices.size() % 2, 0u);
  const std::size_t ring = (mesh.vertices.size() - 2) / 2;
  EXPECT_EQ(mesh.triangles.size(), 4 * ring);
}

}  // namespace
}  // namespace lathesim::sim
