#include "measure/thread_measure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace lathesim::measure {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kBisections = 16;  // a 2.5 mm bracket to 4e-5 mm

Spread spreadOf(const std::vector<double>& values) {
  Spread s{0, values.front(), values.front()};
  for (double v : values) {
    s.mean += v / static_cast<double>(values.size());
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
  }
  return s;
}

// The surface radius along rays at azimuth φ, one per z: the crossing of φ from material to
// air between rLow and rHigh (an external thread: material below; internal: above). A ray
// with no material in the bracket gives the bracket's air end, one all in material its other.
std::vector<double> surfaceRadii(const sim::Stock& stock, double phi, const std::vector<double>& zs, double rLow,
                                 double rHigh, bool internal) {
  std::vector<double> lo(zs.size(), rLow), hi(zs.size(), rHigh);
  std::vector<Eigen::Vector3d> points(zs.size());
  std::vector<double> values(zs.size());
  const double c = std::cos(phi), s = std::sin(phi);
  const auto sample = [&](const std::vector<double>& radii) {
    for (std::size_t i = 0; i < zs.size(); ++i) points[i] = {radii[i] * c, radii[i] * s, zs[i]};
    stock.signedDistancesAt(points, values);
  };
  // Material at lo (external) means φ < 0 there; the ends first, to saturate rays that never cross.
  sample(lo);
  std::vector<double> atLow = values;
  sample(hi);
  std::vector<double> atHigh = values;
  std::vector<double> radius(zs.size());
  std::vector<char> searching(zs.size(), 1);
  for (std::size_t i = 0; i < zs.size(); ++i) {
    const bool lowIsMaterial = atLow[i] < 0, highIsMaterial = atHigh[i] < 0;
    if (lowIsMaterial == highIsMaterial) {  // no crossing: all air (the air end) or all material
      const bool air = !lowIsMaterial;
      radius[i] = internal ? (air ? rHigh : rLow) : (air ? rLow : rHigh);
      searching[i] = 0;
    }
  }
  for (int step = 0; step < kBisections; ++step) {
    std::vector<double> mid(zs.size());
    for (std::size_t i = 0; i < zs.size(); ++i) mid[i] = 0.5 * (lo[i] + hi[i]);
    sample(mid);
    for (std::size_t i = 0; i < zs.size(); ++i) {
      if (!searching[i]) continue;
      const bool material = values[i] < 0;
      // External: material below the surface; internal: above.
      if (material != internal) lo[i] = mid[i];
      else hi[i] = mid[i];
    }
  }
  for (std::size_t i = 0; i < zs.size(); ++i)
    if (searching[i]) radius[i] = 0.5 * (lo[i] + hi[i]);
  return radius;
}

// Where the profile r(z) crosses `level` between samples a and a+1 (linear).
double crossingZ(const std::vector<double>& zs, const std::vector<double>& r, std::size_t a, double level) {
  const double t = (level - r[a]) / (r[a + 1] - r[a]);
  return zs[a] + t * (zs[a + 1] - zs[a]);
}

struct Groove {
  double leftZ[3], rightZ[3];  // flank crossings at the quarter, half and three-quarter radii
  double centreZ = 0;
  double rootR = 0;
};

struct AngleProfile {
  std::vector<Groove> grooves;
  std::vector<double> crestR;
  double pitch = 0;
  double pitchRadius = 0;
  double leftFlankDeg = 0, rightFlankDeg = 0;
  bool ok = false;
};

// The grooves of one profile. `depthSign` is +1 when the root lies below the crest (external).
AngleProfile grooves(const std::vector<double>& zs, const std::vector<double>& r, double rootR, double crestR,
                     double maxWidth, int depthSign) {
  AngleProfile profile;
  const double levels[3] = {rootR + 0.25 * (crestR - rootR), rootR + 0.5 * (crestR - rootR),
                            rootR + 0.75 * (crestR - rootR)};
  // "Deep": on the root's side of a level.
  const auto deep = [&](std::size_t i, double level) { return depthSign * (r[i] - level) < 0; };
  std::size_t i = 0;
  // Skip to the first crest (a sample above the mid level).
  while (i < r.size() && deep(i, levels[1])) ++i;
  std::size_t lastCrestEnd = i;
  while (i < r.size()) {
    while (i < r.size() && !deep(i, levels[1])) ++i;  // along the crest
    if (i >= r.size()) break;
    const std::size_t enter = i;  // first deep sample
    while (i < r.size() && deep(i, levels[1])) ++i;
    if (i >= r.size()) break;  // no crest after it: the part's end
    const std::size_t leave = i;  // first sample past the groove
    // The crest before it, between the last groove and this one.
    double crest = r[lastCrestEnd];
    for (std::size_t k = lastCrestEnd; k < enter; ++k) crest = depthSign > 0 ? std::max(crest, r[k]) : std::min(crest, r[k]);
    lastCrestEnd = leave;
    if (zs[leave] - zs[enter] > maxWidth) continue;  // a relief, the air past the part: not a groove
    // The groove's deepest sample, and from it outward to each level's crossings.
    std::size_t bottom = enter;
    for (std::size_t k = enter; k < leave; ++k)
      if (depthSign * (r[k] - r[bottom]) < 0) bottom = k;
    Groove g;
    g.rootR = r[bottom];
    bool complete = true;
    for (int q = 0; q < 3 && complete; ++q) {
      if (!deep(bottom, levels[q])) {  // shallower than this level: not a full groove
        complete = false;
        break;
      }
      std::size_t a = bottom, b = bottom;
      while (a > 0 && deep(a - 1, levels[q])) --a;
      while (b + 1 < r.size() && deep(b + 1, levels[q])) ++b;
      if (a == 0 || b + 1 >= r.size()) {
        complete = false;
        break;
      }
      g.leftZ[q] = crossingZ(zs, r, a - 1, levels[q]);
      g.rightZ[q] = crossingZ(zs, r, b, levels[q]);
    }
    if (!complete) continue;
    g.centreZ = 0.5 * (g.leftZ[1] + g.rightZ[1]);
    if (!profile.grooves.empty()) profile.crestR.push_back(crest);
    profile.grooves.push_back(g);
  }
  if (profile.grooves.size() < 2) return profile;

  // The pitch: a straight line through the centres against their count (a missing groove
  // counts as one).
  const auto& gs = profile.grooves;
  std::vector<double> gaps;
  for (std::size_t k = 1; k < gs.size(); ++k) gaps.push_back(gs[k].centreZ - gs[k - 1].centreZ);
  std::vector<double> sorted = gaps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  const double typical = sorted[sorted.size() / 2];
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < gs.size(); ++k) {
    const double n = std::round((gs[k].centreZ - gs[0].centreZ) / typical);
    sx += n;
    sy += gs[k].centreZ;
    sxx += n * n;
    sxy += n * gs[k].centreZ;
  }
  const double count = static_cast<double>(gs.size());
  profile.pitch = (count * sxy - sx * sy) / (count * sxx - sx * sx);

  // Flank angles, and the radius where the groove is half a pitch wide (its width is linear
  // in r across straight flanks: fitted through the three levels).
  double left = 0, right = 0, wx = 0, wy = 0, wxx = 0, wxy = 0;
  for (const Groove& g : gs) {
    const double dr = std::abs(levels[2] - levels[0]);
    left += std::atan(std::abs(g.leftZ[2] - g.leftZ[0]) / dr);
    right += std::atan(std::abs(g.rightZ[2] - g.rightZ[0]) / dr);
    for (int q = 0; q < 3; ++q) {
      const double w = g.rightZ[q] - g.leftZ[q];
      wx += levels[q];
      wy += w;
      wxx += levels[q] * levels[q];
      wxy += levels[q] * w;
    }
  }
  profile.leftFlankDeg = left / count * 180 / kPi;
  profile.rightFlankDeg = right / count * 180 / kPi;
  const double m = 3 * count;
  const double slope = (m * wxy - wx * wy) / (m * wxx - wx * wx);
  const double intercept = (wy - slope * wx) / m;
  profile.pitchRadius = (profile.pitch / 2 - intercept) / slope;
  profile.ok = !profile.crestR.empty();
  return profile;
}

}  // namespace

ThreadMeasurement measureThread(const sim::Stock& stock, const ProgrammedThread& thread, const interp::Toolpath& toolpath,
                                const ConvexPolygon& tool) {
  ThreadMeasurement result;
  if (!thread.leadAlongZ) {
    result.problem = "a face thread: not measured";
    return result;
  }
  const double h = stock.voxelMm();
  const int depthSign = thread.internal ? -1 : 1;
  // The tool's point (its deepest vertex) relative to the programmed point, and its reach.
  RZ point = tool.vertices().front();
  for (const RZ& v : tool.vertices())
    if (depthSign * (v.x() - point.x()) < 0 || (v.x() == point.x() && std::abs(v.y()) < std::abs(point.y()))) point = v;
  const double toolHeight = tool.upperBound().x() - tool.lowerBound().x();
  const double programmedRootR = thread.rootRadiusMm + point.x();
  const double rLow = thread.internal ? programmedRootR - toolHeight - 3 * h : programmedRootR - 3 * h;
  const double rHigh = thread.internal ? programmedRootR + 3 * h : programmedRootR + toolHeight + 3 * h;

  std::vector<double> zs;
  for (double z = thread.zMinMm; z <= thread.zMaxMm; z += h / 2) zs.push_back(z);
  const double programmedPitch = thread.leadMm / thread.starts;

  std::vector<AngleProfile> profiles;
  std::vector<double> majors, minors, pitchDiameters, pitches, lefts, rights;
  for (int j = 0; j < kThreadAngles; ++j) {
    const double phi = 2 * kPi * j / kThreadAngles;
    result.anglesDeg.push_back(360.0 * j / kThreadAngles);
    const std::vector<double> r = surfaceRadii(stock, phi, zs, rLow, rHigh, thread.internal);
    // The crest: the outermost (external) radius found, short of the bracket's end.
    double crest = programmedRootR;
    for (double v : r)
      if (std::abs(v - (thread.internal ? rLow : rHigh)) > 1e-9) crest = depthSign > 0 ? std::max(crest, v) : std::min(crest, v);
    AngleProfile profile = grooves(zs, r, programmedRootR, crest, 1.5 * programmedPitch, depthSign);
    if (!profile.ok) {
      result.problem = "fewer than two complete grooves at " + std::to_string(360 * j / kThreadAngles) + "°";
      return result;
    }
    double crestMean = 0, rootMean = 0;
    for (double c : profile.crestR) crestMean += c / static_cast<double>(profile.crestR.size());
    for (const Groove& g : profile.grooves) rootMean += g.rootR / static_cast<double>(profile.grooves.size());
    (thread.internal ? minors : majors).push_back(2 * crestMean);
    (thread.internal ? majors : minors).push_back(2 * rootMean);
    pitchDiameters.push_back(2 * profile.pitchRadius);
    pitches.push_back(profile.pitch);
    lefts.push_back(profile.leftFlankDeg);
    rights.push_back(profile.rightFlankDeg);
    result.grooves = j == 0 ? static_cast<int>(profile.grooves.size())
                            : std::min(result.grooves, static_cast<int>(profile.grooves.size()));
    if (j == 0) {
      result.zLowMm = profile.grooves.front().centreZ;
      result.zHighMm = profile.grooves.back().centreZ;
    }
    profiles.push_back(std::move(profile));
  }

  // Around the axis: follow the groove nearest the middle of the span from angle to angle.
  const auto nearest = [](const AngleProfile& p, double z) {
    double best = p.grooves.front().centreZ;
    for (const Groove& g : p.grooves)
      if (std::abs(g.centreZ - z) < std::abs(best - z)) best = g.centreZ;
    return best;
  };
  const double start = nearest(profiles[0], 0.5 * (result.zLowMm + result.zHighMm));
  double followed = start;
  for (int j = 1; j <= kThreadAngles; ++j) followed = nearest(profiles[j % kThreadAngles], followed);
  // After a full turn the groove followed is back at azimuth 0, one lead along (the nearest
  // groove there is that lead away, not the one started from, as each step moves < pitch/2).
  const double advance = followed - start;
  result.leadPerTurnMm = std::abs(advance);
  result.rightHand = advance > 0;
  result.pitchMm = spreadOf(pitches);
  result.starts = std::max(1, static_cast<int>(std::lround(result.leadPerTurnMm / result.pitchMm.mean)));
  std::vector<double> leads;
  for (double p : pitches) leads.push_back(result.starts * p);
  result.leadMm = spreadOf(leads);
  result.majorDiameterMm = spreadOf(majors);
  result.minorDiameterMm = spreadOf(minors);
  result.pitchDiameterMm = spreadOf(pitchDiameters);
  result.leftFlankDeg = spreadOf(lefts);
  result.rightFlankDeg = spreadOf(rights);

  // The start angle: at azimuth φ the last pass's groove passes z_s + σL(−sφ − θ₀)/360 (mod L/starts),
  // z_s its start plus the tool point's offset; so at φ = 0, θ₀ = 360·(z_s − z_c)/(σL).
  const interp::Move& last = toolpath.moves[thread.passes.back().firstMove];
  const double zs0 = last.from.y() + point.y();
  const double period = 360.0 / result.starts;
  double angle = std::fmod(360.0 * (zs0 - profiles[0].grooves.front().centreZ) / (thread.travelSign * thread.leadMm), period);
  if (angle < 0) angle += period;
  result.startAngleDeg = angle > period / 2 ? angle - period : angle;  // in (−period/2, period/2]
  return result;
}

namespace {

// The width along Z of `polygon`'s chord at radius r (0 when the line misses it).
double chordWidthAt(const ConvexPolygon& polygon, double r) {
  const auto& v = polygon.vertices();
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const RZ& a = v[i];
    const RZ& b = v[(i + 1) % v.size()];
    if ((a.x() - r) * (b.x() - r) > 0) continue;
    const double t = a.x() == b.x() ? 0.0 : (r - a.x()) / (b.x() - a.x());
    for (const double z : {a.y() + t * (b.y() - a.y()), a.x() == b.x() ? b.y() : a.y() + t * (b.y() - a.y())}) {
      low = std::min(low, z);
      high = std::max(high, z);
    }
  }
  return high >= low ? high - low : 0.0;
}

}  // namespace

std::optional<std::string> threadToolTooWide(const MeasuredThread& thread, const ConvexPolygon& tool, double voxelMm) {
  const ProgrammedThread& p = thread.programmed;
  if (!p.leadAlongZ) return std::nullopt;
  const double pitch = p.leadMm / p.starts;
  // The crest relative to the programmed point: measured, or the tool's far end.
  const double crest = thread.measured.problem
                           ? (p.internal ? tool.lowerBound().x() + 1e-9 : tool.upperBound().x() - 1e-9)
                           : (p.internal ? thread.measured.minorDiameterMm.mean : thread.measured.majorDiameterMm.mean) / 2 -
                                 p.rootRadiusMm;
  const double width = chordWidthAt(tool, crest);
  if (width <= pitch + voxelMm) return std::nullopt;
  char text[320];
  std::snprintf(text, sizeof text,
                "the threading tool is %.3f mm wide at the thread's crest, more than its pitch of %.3f mm (lead %g, %d "
                "start%s): each pass cuts into the next groove's flank; use a tool for this pitch",
                width, pitch, p.leadMm, p.starts, p.starts == 1 ? "" : "s");
  return std::string(text);
}

std::vector<MeasuredThread> measureThreads(const sim::Stock& stock, const interp::Toolpath& toolpath,
                                           const std::map<int, ConvexPolygon>& tools, interp::Dialect dialect) {
  std::vector<MeasuredThread> threads;
  for (ProgrammedThread& thread : programmedThreads(toolpath, tools, dialect)) {
    const auto tool = tools.find(thread.tool);
    ThreadMeasurement measured;
    if (tool == tools.end()) measured.problem = "its tool is not defined";
    else measured = measureThread(stock, thread, toolpath, tool->second);
    threads.push_back({std::move(thread), std::move(measured)});
  }
  return threads;
}

}  // namespace lathesim::measure
