#pragma once
// A thread measured on the simulated part, not taken from the program: its profile is read
// in the part's meridian half-planes at several angles around the axis, and from each:
//  - the surface radius r(z) along the thread's span, the zero crossing of φ along the ray
//    from the axis (bisection, to 1e-4 mm), every half voxel of Z;
//  - the grooves: runs of r(z) on the root's side of the mid radius (halfway between the
//    programmed root and the crest found) with a crest on both sides, narrower than 1.5
//    pitches (so the part's ends, a relief or the air beyond the face are not grooves);
//  - per groove, where r(z) crosses the radii a quarter, half and three quarters of the way
//    from root to crest on either flank (linear between samples): its centre (the middle of
//    the half-way crossings), its width at those radii, its flank angles (from the radial
//    direction, between the quarter and three-quarter crossings), its root (the deepest r);
//    the crests between grooves;
//  - the pitch: the slope of a straight-line fit of the groove centres against their count;
//    the pitch diameter: where the groove's width (linear in r across the flanks) is half the
//    pitch; major and minor diameters: the crests' and the roots' (an internal thread's the
//    other way round).
// Around the axis, one groove is followed from angle to angle (the nearest groove each step,
// so the steps must advance less than half a pitch: twelve angles measure up to five starts):
// the advance over a full turn is the lead per turn, its sign the hand (+Z as the azimuth
// grows, counter-clockwise seen from +Z: right hand), and lead / pitch the number of starts.
// The lead at each angle is that number of starts × the pitch there. The start angle is read
// from where a groove crosses azimuth 0, against the last pass's start (ThreadMotion's frame).
// Face threads are not measured.

#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "measure/thread_programs.hpp"
#include "sim/stock.hpp"

namespace lathesim::measure {

/// A figure over the angles measured: its mean, least and greatest.
struct Spread {
  double mean = 0, min = 0, max = 0;
  double range() const { return max - min; }
};

struct ThreadMeasurement {
  std::optional<std::string> problem;  // why it could not be measured (then nothing else is set)
  std::vector<double> anglesDeg;       // the azimuths measured
  int grooves = 0;                     // complete grooves found, the fewest at any angle
  double zLowMm = 0, zHighMm = 0;      // where they lie
  Spread pitchMm;
  Spread leadMm;                       // starts × pitch, at each angle
  double leadPerTurnMm = 0;            // a groove's advance along Z over one turn (≥ 0)
  int starts = 0;
  bool rightHand = true;
  double startAngleDeg = 0;            // mod 360/starts, in the direction the spindle turns
  Spread majorDiameterMm, minorDiameterMm, pitchDiameterMm;
  Spread leftFlankDeg, rightFlankDeg;  // the groove's −Z and +Z walls, from the radial direction
};

/// Measures `thread` on `stock`, cut with `tool` (its outline from the programmed point).
ThreadMeasurement measureThread(const sim::Stock& stock, const ProgrammedThread& thread, const interp::Toolpath& toolpath,
                                const ConvexPolygon& tool);

/// The angles measured: twelve, every 30° from 0.
inline constexpr int kThreadAngles = 12;

struct MeasuredThread {
  ProgrammedThread programmed;
  ThreadMeasurement measured;
};

/// Why `tool` is too wide for `thread`, or nullopt: its chord at the thread's crest (the
/// measured crest; the tool's top when the grooves could not be told apart) is wider than
/// the pitch (lead / starts) by more than a voxel, so each pass cuts into the neighbouring
/// groove's flank and the crest between them.
std::optional<std::string> threadToolTooWide(const MeasuredThread& thread, const ConvexPolygon& tool, double voxelMm);

/// Every thread of `toolpath` (thread_programs.hpp), measured on `stock`.
std::vector<MeasuredThread> measureThreads(const sim::Stock& stock, const interp::Toolpath& toolpath,
                                           const std::map<int, ConvexPolygon>& tools, interp::Dialect dialect);

}  // namespace lathesim::measure
