// The part's mesh is closed and manifold — every edge of the STL shared by exactly two
// triangles, read as an STL reader reads it (corners glued by position) — after the
// programs that leave coincident faces ("ghost sheets", ../shared/notes/sweep-math.md):
// face passes repeated at the same Z and one at the bar's own face, pecks that retrace
// their plunge (G74 on the axis and off it, G75), a pass ending where the last began, a
// drill and a cone whose tip lands on a voxel centre. Each runs at several voxel sizes,
// with the whole job shifted along Z by fractions of a voxel, so that faces fall on voxel
// centres, between them, and near the 128-voxel block boundaries.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "interp/base/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {
namespace {

using ZText = std::function<std::string(double)>;  // a Z value as the program writes it, shifted

struct GhostCase {
  const char* name;
  std::vector<RZ> tool;  // outline (radial, axial) from the programmed point
  std::function<std::string(const ZText&)> program;
};

const std::vector<RZ> kSharpTool{{0, 0}, {10, 1}, {12, 12}, {1, 10}};  // the default tool
const std::vector<RZ> kGrooveBlade{{0, 0}, {15, 0}, {15, 3}, {0, 3}};  // 3 mm wide
const std::vector<RZ> kFaceGrooveBlade{{0, 0}, {3, 0}, {3, 15}, {0, 15}};
const std::vector<RZ> kDrill{{0, 0}, {5, 3}, {5, 60}, {0, 60}};        // Φ10, 118° point

const std::vector<GhostCase>& ghostCases() {
  static const std::vector<GhostCase> cases{
      {"G94 passes repeated at the same Z, the first at the bar's face", kSharpTool,
       [](const ZText& z) {
         return "G00 X45 Z" + z(5) + "\nG94 X10 Z" + z(0) + " F0.2\nX10\nZ" + z(-1) + "\nX10\nX20 Z" + z(-2) +
                "\nZ" + z(-2) + "\nG00 X100 Z" + z(50) + "\n";
       }},
      {"G74 pecks on the axis with a drill", kDrill,
       [](const ZText& z) {
         return "G00 X0 Z" + z(2) + "\nG74 R1.0\nG74 Z" + z(-12) + " Q4000 F0.1\nG00 X100 Z" + z(50) + "\n";
       }},
      {"G74 face grooving off the axis, plunges shifted in X", kFaceGrooveBlade,
       [](const ZText& z) {
         return "G00 X10 Z" + z(2) + "\nG74 R0.5\nG74 X20 Z" + z(-4) + " P3000 Q1500 F0.05\nG00 X100 Z" + z(50) + "\n";
       }},
      {"G75 grooves with pecks, shifted in Z, one groove cut twice", kGrooveBlade,
       [](const ZText& z) {
         return "G00 X34 Z" + z(-6) + "\nG75 R0.5\nG75 X20 Z" + z(-10) + " P2000 Q2500 F0.05\nG00 X34 Z" + z(-6) +
                "\nG75 X20 Z" + z(-10) + " P2000 Q2500 F0.05\nG00 X100 Z" + z(50) + "\n";
       }},
      {"turning passes, each ending where the last began, and repeated", kSharpTool,
       [](const ZText& z) {
         return "G00 X24 Z" + z(2) + "\nG01 Z" + z(-4) + " F0.2\nG00 X32\nZ" + z(-4) + "\nX24\nG01 Z" + z(-8) +
                "\nG00 X32\nZ" + z(2) + "\nX24\nG01 Z" + z(-8) + "\nX28\nG00 X100 Z" + z(50) + "\n";
       }},
  };
  return cases;
}

std::string fixed4(double v) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(4);
  out << v;
  return out.str();
}

// Φ30 × 20 bars, the face at the Z shift: at 0.2 mm, 0.45 mm past Z0 puts it 2.25 voxels
// past a block boundary, where issue 10's bars lost a block.
TEST(MeshManifold, GhostSheetProgramsGiveAClosedManifoldStl) {
  for (const double voxelMm : {0.2, 0.25, 0.5})
    for (const double shiftVoxels : {0.0, 0.5, 2.25, 3.37})
      for (const GhostCase& ghost : ghostCases()) {
        const double shift = shiftVoxels * voxelMm;
        const std::string text =
            "G99 G97 S800 M03\n" + ghost.program([&](double zMm) { return fixed4(zMm + shift); }) + "M30\n";
        SCOPED_TRACE(testing::Message() << ghost.name << " at " << voxelMm << " mm, shifted " << shift
                                        << " mm:\n" << text);
        interp::InterpreterOptions options;
        options.startPosition = {50.0, 50.0 + shift};
        options.toolNumbers = {1};
        const interp::InterpretResult interpreted = interp::interpret(text, "ghost.nc", options);
        ASSERT_TRUE(interpreted.ok()) << interp::format(interpreted.diagnostics.front());
        ToolOutlines tools;
        tools.emplace(1, *ConvexPolygon::fromOutline(ghost.tool).polygon);
        Stock stock({30.0, 20.0, shift}, voxelMm);
        simulate(interpreted.toolpath, tools, stock);
        TriangleMesh mesh = stock.mesh(0.002);
        weldCoincidentVertices(mesh);  // as the STL will be read
        EXPECT_TRUE(isClosedAndOriented(mesh));
        EXPECT_NEAR(enclosedVolumeMm3(mesh), stock.volumeMm3(), volumeToleranceMm3(surfaceAreaMm2(mesh), voxelMm));
      }
}

}  // namespace
}  // namespace lathesim::sim
