#include "sim/thread_history.hpp"

#include <cmath>
#include <limits>

#include "geometry/convex_overlap.hpp"

namespace lathesim::sim {
namespace {

// Two passes share a helix when their lead vectors differ by less than this (mm per turn): the
// placements then drift apart by under a millionth of a millimetre over a thousand turns, which
// kPairingSlackMm covers.
constexpr double kLeadVectorTolMm = 1e-9;
constexpr double kPairingSlackMm = 1e-6;

// How one remembered pass pairs with the new one, when it does.
struct Pairing {
  std::vector<ConvexPolygon> slivers;  // the new outline's part outside the earlier one shifted by Δ
  std::vector<ConvexPolygon> zones;    // where the new pass is written whole
  double costMm2 = 0;                  // the areas of both: the pairing that leaves least is used
};

RZ leadVector(const HelicalSweep& sweep) { return sweep.direction() / sweep.revolutions(); }

std::optional<Pairing> pairingOf(const ThreadPass& pass, const HelicalSweep& sweep, const ThreadPass& before) {
  if (before.sense != pass.sense || before.outline.vertices() != pass.outline.vertices()) return std::nullopt;
  const HelicalSweep earlier = before.sweep();
  const RZ lead = leadVector(sweep);
  const double leadSquared = lead.squaredNorm();
  if ((leadVector(earlier) - lead).norm() > kLeadVectorTolMm || !(leadSquared > 0)) return std::nullopt;
  // At azimuth φ a pass places its outline at from + (φ − φ₀)·μ + k·λ, with μ = direction / (dφ/du)
  // the same for both: the offset between the two families, taken as the smallest one.
  const RZ perRadian = sweep.direction() / sweep.radiansPerUnit();
  RZ offset = (pass.from - before.from) - (sweep.startAzimuthRad() - earlier.startAzimuthRad()) * perRadian;
  offset += std::round(-offset.dot(lead) / leadSquared) * lead;
  // The new pass's placement at u pairs with the earlier one's at u' = (c + u·n)/n', which must
  // lie in [0, 1]: u in [uFrom, uTo].
  const double c = (pass.from - before.from - offset).dot(lead) / leadSquared;
  const double uFrom = std::max(0.0, -c / pass.revolutions);
  const double uTo = std::min(1.0, (before.revolutions - c) / pass.revolutions);
  if (!(uFrom < uTo)) return std::nullopt;

  Pairing pairing;
  pairing.slivers = differenceOf(pass.outline, pass.outline.translated(-offset));
  const RZ direction = pass.to - pass.from;
  if (uFrom > 0.0) pairing.zones.push_back(pass.outline.sweptAlong(pass.from, pass.from + uFrom * direction));
  if (uTo < 1.0) pairing.zones.push_back(pass.outline.sweptAlong(pass.from + uTo * direction, pass.to));
  for (const ConvexPolygon& piece : pairing.slivers) pairing.costMm2 += piece.area();
  for (const ConvexPolygon& zone : pairing.zones) pairing.costMm2 += zone.area();
  // Both passes' ends: their faces are measured in 3D, not by the placements.
  for (const RZ& end : {pass.from, pass.to}) pairing.zones.push_back(pass.outline.translated(end));
  for (const RZ& end : {before.from, before.to}) pairing.zones.push_back(before.outline.translated(end));
  return pairing;
}

}  // namespace

ThreadChangeBound::ThreadChangeBound(std::vector<HelicalSweep> slivers, std::vector<ConvexPolygon> zones,
                                     const std::vector<ConvexPolygon>& extent)
    : slivers_(std::move(slivers)), zones_(zones), extent_(extent) {}

bool ThreadChangeBound::mayChange(double x, double y, double z, double spreadMm, double bandMm) const {
  const double rho = std::sqrt(x * x + y * y);
  // The zones are revolved: their distance changes by at most 1 per mm.
  const double reach = spreadMm + bandMm;
  if (!zones_.empty() && zones_.signedDistance(rho, z, reach + 1.0) <= reach) return true;
  for (const HelicalSweep& sliver : slivers_) {
    const double slope = sliver.lipschitzAt(rho - spreadMm);
    if (!std::isfinite(slope)) return true;  // near the axis: no bound
    const double sliverReach = slope * spreadMm + bandMm + kPairingSlackMm;
    if (sliver.signedDistance(x, y, z, sliverReach + 1.0) <= sliverReach) return true;
  }
  return false;
}

std::optional<ThreadChangeBound> ThreadHistory::changesOf(const ThreadPass& pass) {
  const HelicalSweep sweep = pass.sweep();
  std::optional<Pairing> best;
  for (auto before = written_.rbegin(); before != written_.rend(); ++before) {  // newest first: it wins ties
    auto pairing = pairingOf(pass, sweep, *before);
    if (pairing && (!best || pairing->costMm2 < best->costMm2)) best = std::move(pairing);
  }
  written_.push_back(pass);
  if (written_.size() > kRemembered) written_.pop_front();
  if (!best) return std::nullopt;

  std::vector<HelicalSweep> slivers;
  std::vector<ConvexPolygon> extent = best->zones;
  for (const ConvexPolygon& piece : best->slivers) {
    slivers.emplace_back(piece, pass.from, pass.to, pass.revolutions, pass.startSpindleDeg, pass.sense);
    extent.push_back(piece.sweptAlong(pass.from, pass.to));
  }
  return ThreadChangeBound(std::move(slivers), std::move(best->zones), extent);
}

}  // namespace lathesim::sim
