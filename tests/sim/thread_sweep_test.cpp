// A thread pass swept along its helix into the level set (geometry/helical_sweep.hpp):
// the volume it removes against the helical Pappus formula, the hand of the helix, the start
// angle, and cuts made with the spindle stopped (straight slots).
//
// Helical Pappus (../shared/notes/sweep-math.md): a groove whose meridian section is w(r)
// wide at radius r, cut with lead L over an axial length ℓ with no overlap between turns,
// removes V = (2π/L)·ℓ·∫ r·w(r) dr — at each (r, z) the groove takes the fraction w(r)/L of
// the circle. A sharp 60° V of depth h below the bar's radius R: w(r) = 2(r − R + h)·tan 30°,
// so with a = R − h: V = (2π/L)·ℓ·2·tan 30°·((R³ − a³)/3 − a(R² − a²)/2). The pass runs from
// 4 mm beyond the bar's face to 4 mm beyond its far end, so neither end of the groove is in it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/simulate.hpp"
#include "tests/sim/thread_test_support.hpp"

namespace lathesim::sim {
namespace {

constexpr double kPi = std::numbers::pi;
using test::kTan30;
using test::threadMove;

ConvexPolygon sharpVee() { return test::sharpVee(3.0); }  // 3 mm tall

double veeGrooveVolume(double radius, double depth, double lead, double length) {
  const double a = radius - depth;
  const double integral = 2 * kTan30 * ((std::pow(radius, 3) - std::pow(a, 3)) / 3 - a * (radius * radius - a * a) / 2);
  return 2 * kPi / lead * length * integral;
}

struct Groove {
  double depth, lead, voxel;
};

// One G32 pass of a sharp 60° V through a Φ20 × 8 bar: depths, leads (each wider than the
// groove, so turns do not overlap) and voxel sizes. The tolerance is 1 % of a voxel layer over
// the groove's two flanks (area (ℓ/L)·2πR·2h/cos 30°); measured: at most 0.15 of it (3e-4
// relative). A lead off by a tenth of a voxel per turn changes the volume by far more.
TEST(ThreadSweep, SharpVeeRemovesTheHelicalPappusVolume) {
  constexpr double kRadius = 10, kLength = 8;
  for (const Groove g : {Groove{0.5, 1.0, 0.1}, Groove{1.0, 2.0, 0.1}, Groove{1.3, 1.5, 0.07}, Groove{0.8, 3.0, 0.05},
                         Groove{1.0, 2.0, 0.05}}) {
    SCOPED_TRACE(testing::Message() << "h " << g.depth << " L " << g.lead << " voxel " << g.voxel);
    Stock stock({2 * kRadius, kLength, 0.0}, g.voxel);
    const double before = stock.volumeMm3();
    interp::Toolpath path;
    path.blockCount = 1;
    path.moves.push_back(threadMove({kRadius - g.depth, 4}, {kRadius - g.depth, -kLength - 4}, g.lead, 0,
                                    interp::SpindleDirection::Clockwise));
    const SimulationResult result = simulate(path, {{1, sharpVee()}}, stock);
    const double removed = before - stock.volumeMm3();
    const double exact = veeGrooveVolume(kRadius, g.depth, g.lead, kLength);
    const double flanks = kLength / g.lead * 2 * kPi * kRadius * 2 * g.depth / std::cos(kPi / 6);
    EXPECT_NEAR(removed, exact, 0.01 * g.voxel * flanks);
    std::printf("[   info   ] h %.2f L %.2f voxel %.2f: removed %.3f exact %.3f (%+.2e relative, %.3f of the tolerance)\n",
                g.depth, g.lead, g.voxel, removed, exact, (removed - exact) / exact,
                std::abs(removed - exact) / (0.01 * g.voxel * flanks));
    EXPECT_NEAR(result.blocks[0].removedMm3, removed, 1e-6 * before);
  }
}

// A pass that stops inside the bar: the groove ends in a face, the V where the tool stood
// when the pass ended. A point of the V at axial offset δ from its apex is in the bar while the
// apex runs from −δ to −4, over 4 + δ of travel; the V is symmetric in δ, so the groove
// removes the helical Pappus volume of 4 mm exactly. The end lands at several azimuths against
// the grid (start angles). Half a voxel past the end face the bar is untouched material, half
// a voxel short of it the groove is air. A writer that read the groove's points near its end
// as deep as the flanks allow put the face too far (material half a voxel past it read as
// air), and could take a cube straddling the face for covered.
TEST(ThreadSweep, GrooveEndingInsideTheBarEndsInItsFace) {
  constexpr double kRadius = 10, kLength = 8, kTravel = 4;
  for (const Groove g : {Groove{1.0, 2.0, 0.1}, Groove{1.3, 1.5, 0.05}, Groove{0.8, 3.0, 0.07}})
    for (const double startDeg : {0.0, 37.0, 201.5}) {
      SCOPED_TRACE(testing::Message() << "h " << g.depth << " L " << g.lead << " voxel " << g.voxel << " Q "
                                      << startDeg);
      Stock stock({2 * kRadius, kLength, 0.0}, g.voxel);
      const double before = stock.volumeMm3();
      interp::Toolpath path;
      path.blockCount = 1;
      path.moves.push_back(threadMove({kRadius - g.depth, kTravel}, {kRadius - g.depth, -kTravel}, g.lead, startDeg,
                                      interp::SpindleDirection::Clockwise));
      simulate(path, {{1, sharpVee()}}, stock);
      const double removed = before - stock.volumeMm3();
      const double exact = veeGrooveVolume(kRadius, g.depth, g.lead, kTravel);
      const double flanks = kTravel / g.lead * 2 * kPi * kRadius * 2 * g.depth / std::cos(kPi / 6);
      const double endFace = g.depth * g.depth * kTan30;
      EXPECT_NEAR(removed, exact, 0.01 * g.voxel * flanks + 0.1 * g.voxel * endFace);
      // M03: the tool ends at the part's azimuth −Q − 360°·n and came from larger azimuths,
      // where the groove stood higher by a lead a turn. Points on the V's centre line, from
      // four voxels above its apex (two voxels from the flanks) to a voxel under the bar's face.
      const double endAzimuth = -startDeg * kPi / 180 - 2 * kPi * (2 * kTravel / g.lead);
      const double offset = 0.5 * g.voxel;
      for (double r = kRadius - g.depth + 4 * g.voxel; r < kRadius - g.voxel; r += g.voxel / 3) {
        const double past = endAzimuth - offset / r, short_ = endAzimuth + offset / r;
        const double zShort = -kTravel + g.lead * (offset / r) / (2 * kPi);
        EXPECT_LT(stock.signedDistanceAt(r * std::cos(past), r * std::sin(past), -kTravel), -0.25 * g.voxel) << "r " << r;
        EXPECT_GT(stock.signedDistanceAt(r * std::cos(short_), r * std::sin(short_), zShort), 0.25 * g.voxel) << "r " << r;
      }
    }
}

// The groove's centre along z at azimuth φ (radians), on the circle of radius r: where the
// level set is highest over one lead searched from z0.
double grooveCentreZ(const Stock& stock, double r, double phi, double z0, double lead) {
  double best = -1e9, bestZ = z0;
  for (double z = z0; z < z0 + lead; z += lead / 400) {
    const double value = stock.signedDistanceAt(r * std::cos(phi), r * std::sin(phi), z);
    if (value > best) {
      best = value;
      bestZ = z;
    }
  }
  return bestZ;
}

// (z_b − z_a) taken modulo the lead into [−L/2, L/2).
double advance(double za, double zb, double lead) {
  const double d = std::fmod(zb - za, lead);
  const double positive = d < 0 ? d + lead : d;
  return positive >= lead / 2 ? positive - lead : positive;
}

// M03 feeding toward the chuck cuts a right-hand thread: going a quarter turn around the part
// (azimuth +90°, counter-clockwise seen from +Z) the groove is a quarter lead further toward
// +Z. M04 is left-hand: a quarter lead toward −Z. Flipping the hand swaps the two, so this
// fails whichever way the hand is lost.
TEST(ThreadSweep, RightAndLeftHandThreads) {
  constexpr double kLead = 2.0, kVoxel = 0.1;
  for (const auto direction : {interp::SpindleDirection::Clockwise, interp::SpindleDirection::CounterClockwise}) {
    Stock stock({20.0, 10.0, 0.0}, kVoxel);
    interp::Toolpath path;
    path.blockCount = 1;
    path.moves.push_back(threadMove({9, 4}, {9, -14}, kLead, 0, direction));
    simulate(path, {{1, sharpVee()}}, stock);
    const double z0 = grooveCentreZ(stock, 9.5, 0.0, -6, kLead);
    const double z90 = grooveCentreZ(stock, 9.5, kPi / 2, z0 - kLead / 2, kLead);
    const double expected = direction == interp::SpindleDirection::Clockwise ? kLead / 4 : -kLead / 4;
    EXPECT_NEAR(advance(z0, z90, kLead), expected, 2 * kLead / 400 + 0.02);
  }
}

// The pass starts when the spindle reaches θ₀ = Q: the tool then stands at the part's azimuth
// −θ₀, so at azimuth φ the groove passes z_start + L·(θ₀ + φ)/360° (mod L) for M03 toward −Z.
// A start shifted by Q90000 puts the groove a quarter lead further along +Z at every angle.
TEST(ThreadSweep, StartAngleShiftsTheGroove) {
  constexpr double kLead = 2.0, kVoxel = 0.1;
  double centres[2][4];
  for (int shifted = 0; shifted < 2; ++shifted) {
    Stock stock({20.0, 10.0, 0.0}, kVoxel);
    interp::Toolpath path;
    path.blockCount = 1;
    path.moves.push_back(threadMove({9, 4}, {9, -14}, kLead, shifted ? 90.0 : 0.0, interp::SpindleDirection::Clockwise));
    simulate(path, {{1, sharpVee()}}, stock);
    for (int q = 0; q < 4; ++q) centres[shifted][q] = grooveCentreZ(stock, 9.5, q * kPi / 2, -6, kLead);
  }
  for (int q = 0; q < 4; ++q) {
    SCOPED_TRACE(testing::Message() << "azimuth " << 90 * q << "°");
    // Unshifted: z ≡ 4 + L·φ/360 (mod L); shifted: a quarter lead more.
    EXPECT_NEAR(advance(4.0 + kLead * q / 4.0, centres[0][q], kLead), 0.0, 0.03);
    EXPECT_NEAR(advance(centres[0][q], centres[1][q], kLead), kLead / 4, 0.03);
  }
}

// A feed with the spindle stopped at 90° cuts a slot in the part's half-plane at azimuth −90°
// (y < 0), as wide as the insert, and nothing on the other side. A 4 × 4 square plunged
// radially to r 12 at Z-4 on a Φ40 bar, 3 mm thick: in the tool's plane the section is
// r 12…20 (within the bar) × Z-4…0, so the slot is {x' ∈ [12, r(y)], |y'| ≤ 1.5} × 4 mm:
// 4·∫ (√(400 − y²) − 12) dy over |y| ≤ 1.5.
TEST(StraightSlot, FeedWithTheSpindleStoppedCutsASlotAtItsAngle) {
  for (const double voxel : {0.1, 0.07}) {
    SCOPED_TRACE(testing::Message() << "voxel " << voxel);
    Stock stock({40.0, 20.0, 0.0}, voxel);
    const double before = stock.volumeMm3();
    interp::Toolpath path;
    path.blockCount = 1;
    interp::Move plunge = threadMove({25, -4}, {12, -4}, 1, 0, interp::SpindleDirection::Clockwise);
    plunge.kind = interp::MoveKind::Feed;
    plunge.spindleOn = false;
    plunge.spindleAngleDeg = 90;
    path.moves.push_back(plunge);
    const std::vector<RZ> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    simulate(path, {{1, *ConvexPolygon::fromOutline(square).polygon}}, stock, {{}, nullptr, {{1, 3.0}}, {}});
    const double y = 1.5;
    const double chord = y * std::sqrt(400 - y * y) + 400 * std::asin(y / 20);  // ∫_{−y}^{y} √(400 − t²) dt
    const double exact = 4 * (chord - 12 * 2 * y);
    const double surface = 2 * 8 * 4 + 2 * 3 * 4 + 8 * 3;  // the slot's walls and floor (about)
    EXPECT_NEAR(before - stock.volumeMm3(), exact, 0.1 * voxel * surface);
    EXPECT_GT(stock.signedDistanceAt(0, -15, -2), voxel);   // the slot, at azimuth −90°
    EXPECT_LT(stock.signedDistanceAt(0, 15, -2), -voxel);   // untouched at +90°
    EXPECT_LT(stock.signedDistanceAt(15, 0, -2), -voxel);   // and at 0°
  }
}

}  // namespace
}  // namespace lathesim::sim
