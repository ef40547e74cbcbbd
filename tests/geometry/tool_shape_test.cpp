// Tool outlines placed at the imaginary tip. Expected numbers are worked out by hand from
// iso-tools.md §2.11: the nose centre lies r/sin(ε/2) from the sharp corner P along the corner
// bisector β, and the tip-3 point (the tangent corner) sits ΔZ = r(cos β / sin(ε/2) − 1),
// ΔX = r(sin β / sin(ε/2) − 1) from P (Sumitomo's "position of cutting point" table).

#include "geometry/tool_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lathesim {
namespace {

constexpr double kPi = std::numbers::pi;

ToolShape turning(std::string_view insertCode, std::string_view holderCode, std::optional<int> tip = std::nullopt) {
  const auto insert = parseIsoInsert(insertCode);
  const auto holder = parseIsoHolder(holderCode);
  EXPECT_TRUE(insert.value && holder.value);
  const BuiltTool built = turningTool(*insert.value, *holder.value, tip);
  EXPECT_TRUE(built.tool) << built.problem;
  return *built.tool;
}

/// Convex, counter-clockwise, as a user-given outline would have to be.
void expectConvex(const ConvexPolygon& p) {
  const auto checked = ConvexPolygon::fromOutline(p.vertices());
  ASSERT_TRUE(checked.polygon) << checked.problem;
  EXPECT_EQ(checked.polygon->vertices().size(), p.vertices().size());
  EXPECT_GT(p.area(), 0.0);
}

/// The vertices within `reach` of the nose centre lie on the nose circle, and the chords between
/// consecutive ones stay within 0.005 mm of it.
void expectNoseArc(const ToolShape& tool, double reach) {
  const auto& v = tool.cutter.vertices();
  int onArc = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double d = (v[i] - tool.noseCentre).norm();
    if (d > reach) continue;
    ++onArc;
    EXPECT_NEAR(d, tool.noseRadiusMm, 1e-9);
    const RZ& next = v[(i + 1) % v.size()];
    if ((next - tool.noseCentre).norm() <= reach) {
      const double mid = ((v[i] + next) / 2 - tool.noseCentre).norm();
      EXPECT_GT(mid, tool.noseRadiusMm - 0.005);
    }
  }
  EXPECT_GE(onArc, 5);
}

TEST(ToolShape, SeedsSTFCRWithTBHGIsDefinedByItsTwoCodes) {
  const auto insert = parseIsoInsert("TBHG120408");
  const auto holder = parseIsoHolder("STFCR2525M11");
  ASSERT_TRUE(insert.value && holder.value);
  const BuiltTool built = turningTool(*insert.value, *holder.value, std::nullopt);
  ASSERT_TRUE(built.tool) << built.problem;
  // The pair disagrees on the seat (size 11 vs 12) and clearance (C vs B): warnings, not errors.
  ASSERT_EQ(built.warnings.size(), 2u);
  EXPECT_NE(built.warnings[0].find("size 12 but holder STFCR2525M11 seats size 11"), std::string::npos);
  const ToolShape& t = *built.tool;
  EXPECT_EQ(t.tipNumber, 3);  // R-hand external holder
  EXPECT_DOUBLE_EQ(t.noseRadiusMm, 0.8);
  expectConvex(t.cutter);
  expectNoseArc(t, 0.81);
  // Style F (end-cutting, κr 90°) with ε 60°: β = κr − 90° + ε/2 = 30°. Its major edge runs along
  // Z and the minor edge at 60°, so the nose arc faces −X and −Z and the tip-3 point is the
  // outline's lowest radial and lowest axial point: lower bound (0, 0).
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.lowerBound().y(), 0.0, 1e-9);
  // Nose centre (r, r) from the programmed point.
  EXPECT_NEAR(t.noseCentre.x(), 0.8, 1e-9);
  EXPECT_NEAR(t.noseCentre.y(), 0.8, 1e-9);
  // Sharp corner: ΔZ = 0.8(cos 30°/sin 30° − 1) = 0.5856, ΔX = 0.8(sin 30°/sin 30° − 1) = 0.
  EXPECT_NEAR(t.sharpCorner.x(), 0.0, 1e-9);
  EXPECT_NEAR(t.sharpCorner.y(), -0.8 * (std::sqrt(3.0) - 1), 1e-9);
  // The triangle's top corner is l·sin 60° = 10.392 above P; rounded, its top is 2r − r = r lower:
  // 10.392 − 0.8 = 9.592 (P is at radial 0 here).
  EXPECT_NEAR(t.cutter.upperBound().x(), 12.0 * std::sin(kPi / 3) - 0.8, 1e-6);
  // Holder: the shank's back face is f = 32 from P in +Z, its end l1 = 150 above P; the body
  // stays clear of the nose.
  ASSERT_TRUE(t.holderBody);
  EXPECT_NEAR(t.holderBody->upperBound().y(), 32.0 + t.sharpCorner.y(), 1e-9);
  EXPECT_NEAR(t.holderBody->upperBound().x(), 150.0, 1e-9);
  EXPECT_GT(t.holderBody->signedDistance(t.noseCentre), 0.8);
  expectConvex(*t.holderBody);
}

TEST(ToolShape, PCLNRWithCNMGMatchesTheCatalogueCuttingPoint) {
  // L95/C80, r 0.8: β = 180 − 95 − 40 = 45°; ΔZ = ΔX = 0.8(sin 45°/sin 40° − 1) = 0.0800 (Sumitomo 0.08/0.08).
  const ToolShape t = turning("CNMG120408", "PCLNR2525M12");
  EXPECT_EQ(t.tipNumber, 3);
  EXPECT_NEAR(t.sharpCorner.x(), -0.0800, 0.0005);
  EXPECT_NEAR(t.sharpCorner.y(), -0.0800, 0.0005);
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.lowerBound().y(), 0.0, 1e-9);
  expectConvex(t.cutter);
  expectNoseArc(t, 0.81);
  // Rhombus: the opposite acute corner is 2·l·cos 40° = 2·12.896·0.7660 = 19.76 from P along β = 45°.
  const double far = 2 * 12.70 / std::sin(80 * kPi / 180) * std::cos(40 * kPi / 180);
  // Its nose centre is r/sin 40° = 1.245 back along β, and the outline's top is r above that centre.
  const double farNoseCentre = far - 0.8 / std::sin(40 * kPi / 180);
  EXPECT_NEAR(t.cutter.upperBound().x(), t.sharpCorner.x() + farNoseCentre * std::sin(kPi / 4) + 0.8, 1e-9);
}

TEST(ToolShape, PDJNRWithDNMGMatchesTheCatalogueCuttingPoint) {
  // J93/D55, r 0.8: β = 180 − 93 − 27.5 = 59.5°; ΔX = 0.8(sin 59.5°/sin 27.5° − 1) = 0.693,
  // ΔZ = 0.8(cos 59.5°/sin 27.5° − 1) = 0.079 (Sumitomo 0.69 / 0.08).
  const ToolShape t = turning("DNMG150608", "PDJNR2525M15");
  EXPECT_NEAR(t.sharpCorner.x(), -0.693, 0.001);
  EXPECT_NEAR(t.sharpCorner.y(), -0.079, 0.001);
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);  // κr' = 180 − 93 − 55 = 32° ≥ 0
  EXPECT_NEAR(t.cutter.lowerBound().y(), 0.0, 1e-9);
  expectConvex(t.cutter);
}

TEST(ToolShape, LeftHandMirrorsToTip4) {
  const ToolShape t = turning("CNMG120408", "PCLNL2525M12");
  EXPECT_EQ(t.tipNumber, 4);  // (−X, +Z) from the nose centre
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.upperBound().y(), 0.0, 1e-9);
  EXPECT_NEAR(t.noseCentre.x(), 0.8, 1e-9);
  EXPECT_NEAR(t.noseCentre.y(), -0.8, 1e-9);
  EXPECT_LT(t.holderBody->upperBound().y(), 0.0);  // the shank lies on the tailstock side's mirror: −Z
}

TEST(ToolShape, TipOverrideMovesTheProgrammedPoint) {
  EXPECT_TRUE(turning("CNMG120408", "PCLNR2525M12", 8).noseCentre.isApprox(RZ(0.8, 0.0)));
  EXPECT_NEAR(turning("CNMG120408", "PCLNR2525M12", 0).noseCentre.norm(), 0.0, 1e-12);
  EXPECT_TRUE(turning("CNMG120408", "PCLNR2525M12", 1).noseCentre.isApprox(RZ(-0.8, -0.8)));
}

TEST(ToolShape, RoundInsertInANeutralHolder) {
  const ToolShape t = turning("RCMT1204M0", "SRDCN2525M12");
  EXPECT_EQ(t.tipNumber, 8);  // N hand: touched off on the centre line
  EXPECT_TRUE(t.noseCentre.isApprox(RZ(6.0, 0.0)));
  for (const RZ& v : t.cutter.vertices()) EXPECT_NEAR((v - t.noseCentre).norm(), 6.0, 1e-9);
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.area(), kPi * 36.0, kPi * 36.0 * 0.002);
}

TEST(ToolShape, OtherFamiliesBuildConvexOutlines) {
  for (const auto& [insert, holder] : std::vector<std::pair<const char*, const char*>>{
           {"VBMT160404", "SVJBR2525M16"}, {"TNMG160408", "MTJNR2525M16"}, {"WNMG080408", "PWLNR2525M08"},
           {"SNMG120408", "PSDNN2525M12"}, {"CCMT060204", "SCLCR1616H06"}, {"VBMT160404", "SVVBN2525M16"}}) {
    SCOPED_TRACE(std::string(insert) + " in " + holder);
    const ToolShape t = turning(insert, holder);
    expectConvex(t.cutter);
    expectNoseArc(t, t.noseRadiusMm + 0.01);
    ASSERT_TRUE(t.holderBody);
    EXPECT_GT(t.holderBody->signedDistance(t.noseCentre), t.noseRadiusMm);
  }
}

TEST(ToolShapeErrors, InsertMustFitTheHolderShape) {
  const BuiltTool built = turningTool(*parseIsoInsert("CNMG120408").value, *parseIsoHolder("PDJNR2525M15").value, 3);
  EXPECT_FALSE(built.tool);
  EXPECT_EQ(built.problem, "insert CNMG120408 is shape C but holder PDJNR2525M15 seats shape D");
}

TEST(ToolShape, GrooveBlade) {
  // 3 wide, both end corners r 0.4, 20 deep: area 3·20 − 2·(1 − π/4)·0.4² = 59.9313.
  const BuiltTool built = grooveTool(3.0, 0.4, 0.4, 20.0, std::nullopt);
  ASSERT_TRUE(built.tool) << built.problem;
  const ToolShape& t = *built.tool;
  EXPECT_EQ(t.tipNumber, 3);
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.lowerBound().y(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.upperBound().x(), 20.0, 1e-9);
  EXPECT_NEAR(t.cutter.upperBound().y(), 3.0, 1e-9);
  // Chords lose at most arc length × sagitta: 2 quarter arcs · (π/2 · 0.4) · 0.004 = 0.005.
  const double exact = 60.0 - 2.0 * (1.0 - kPi / 4) * 0.16;
  EXPECT_LT(t.cutter.area(), exact);
  EXPECT_GT(t.cutter.area(), exact - 0.005);
  expectConvex(t.cutter);
  expectNoseArc(t, 0.41);
  const ToolShape right = *grooveTool(3.0, 0.4, 0.4, 20.0, 4).tool;  // the +Z corner
  EXPECT_NEAR(right.cutter.upperBound().y(), 0.0, 1e-9);
  EXPECT_TRUE(right.noseCentre.isApprox(RZ(0.4, -0.4)));
  const ToolShape middle = *grooveTool(3.0, 0.4, 0.4, 20.0, 8).tool;
  EXPECT_NEAR(middle.cutter.lowerBound().y(), -1.5, 1e-9);
  EXPECT_EQ(grooveTool(3.0, 0.4, 0.4, 20.0, 5).problem, "tip 5 does not apply to a groove tool; expected 3, 4, 8");
  EXPECT_FALSE(grooveTool(3.0, 2.0, 1.5, 20.0, 3).tool);  // 2 + 1.5 > 3
}

TEST(ToolShape, GrooveBladeWithUnequalCorners) {
  // Left r 0.2, right r 0.8 on a 4 wide blade: area 4·10 − (1 − π/4)(0.04 + 0.64); at tip 4 the
  // nose is the 0.8 corner, (0.8, −0.8) from the programmed point.
  const ToolShape t = *grooveTool(4.0, 0.2, 0.8, 10.0, 4).tool;
  EXPECT_NEAR(t.cutter.area(), 40.0 - (1.0 - kPi / 4) * 0.68, 0.005);
  EXPECT_DOUBLE_EQ(t.noseRadiusMm, 0.8);
  EXPECT_TRUE(t.noseCentre.isApprox(RZ(0.8, -0.8)));
  EXPECT_NEAR(t.cutter.lowerBound().y(), -4.0, 1e-9);
  expectNoseArc(t, 0.81);
}

TEST(ToolShape, ThreadInsert) {
  // 60°, P 2, r 0.25: the fundamental triangle is H = 2/(2·tan 30°) = 1.732 tall and 2 wide at the
  // top; the nose centre is r/sin 30° = 0.5 above the sharp apex, so the point (tip 8) is 0.25
  // above it and the top lies 1.732 − 0.25 = 1.482 above the programmed point.
  const BuiltTool built = threadTool(60.0, 2.0, 0.25, std::nullopt);
  ASSERT_TRUE(built.tool) << built.problem;
  const ToolShape& t = *built.tool;
  EXPECT_EQ(t.tipNumber, 8);
  EXPECT_NEAR(t.cutter.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(t.cutter.upperBound().x(), std::sqrt(3.0) - 0.25, 1e-9);
  EXPECT_NEAR(t.cutter.lowerBound().y(), -1.0, 1e-9);
  EXPECT_NEAR(t.cutter.upperBound().y(), 1.0, 1e-9);
  EXPECT_TRUE(t.noseCentre.isApprox(RZ(0.25, 0.0)));
  expectConvex(t.cutter);
  expectNoseArc(t, 0.26);
  EXPECT_NE(threadTool(60.0, 2.0, 0.25, 3).problem.find("tip 3 does not apply to a thread tool"), std::string::npos);
}

TEST(ToolShape, Drill) {
  // Φ10, 118°: point length 5/tan 59° = 3.004; area (both sides of the axis) = 10·50 − 5·3.004.
  const BuiltTool built = drillTool(10.0, 118.0, 50.0);
  ASSERT_TRUE(built.tool) << built.problem;
  const double pointLength = 5.0 / std::tan(59.0 * kPi / 180);
  EXPECT_NEAR(built.tool->cutter.area(), 500.0 - 5.0 * pointLength, 1e-9);
  EXPECT_EQ(built.tool->tipNumber, 0);
  EXPECT_NEAR(built.tool->cutter.lowerBound().y(), 0.0, 1e-12);
  EXPECT_FALSE(drillTool(10.0, 118.0, 2.0).tool);
}

// A radius no tool has (a thread of pitch 555 555 552 mm, as the ISO code harness named it in
// a comment: a 69 km nose) is drawn with a bounded number of chords, each within a millionth
// of the radius; it was 300 000 chords and seconds for one comment. The V is still that
// pitch wide at its top.
TEST(ToolShape, ANoseOfKilometresTakesABoundedNumberOfChords) {
  const double pitch = 555555552.0;
  const BuiltTool built = threadTool(55.0, pitch, 0.125 * pitch, std::nullopt);
  ASSERT_TRUE(built.tool) << built.problem;
  EXPECT_LT(built.tool->cutter.vertices().size(), 3000u);
  EXPECT_NEAR(built.tool->cutter.lowerBound().y(), -pitch / 2, 1e-6 * pitch);
  EXPECT_NEAR(built.tool->cutter.upperBound().y(), pitch / 2, 1e-6 * pitch);
}

}  // namespace
}  // namespace lathesim
