#include "render/drawn_toolpath.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/arc.hpp"

namespace lathesim::render {
namespace {

// A merged run checks each of its points against every longer segment: past this many points
// it is closed, so that a move costs a bounded time however long the straight run.
constexpr std::size_t kRunPointsAtMost = 128;

bool straight(interp::MoveKind kind) { return !interp::isArc(kind) && kind != interp::MoveKind::Dwell; }

double distanceToSegment(const RZ& p, const RZ& a, const RZ& b) {
  const RZ ab = b - a;
  const double lengthSquared = ab.squaredNorm();
  const double t = lengthSquared > 0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

std::size_t DrawnToolpath::KeyHash::operator()(const Key& key) const {
  std::size_t h = static_cast<std::size_t>(key.kind);
  for (const std::int64_t cell : key.cells) h = h * 1000003u ^ std::hash<std::int64_t>{}(cell);
  return h;
}

DrawnToolpath::DrawnToolpath(double toleranceMm, std::size_t maxMoves)
    : toleranceMm_(toleranceMm), errorBoundMm_(toleranceMm), maxMoves_(std::max<std::size_t>(maxMoves, 2)) {}

void DrawnToolpath::take(interp::Move move) {
  lastTaken_ = move;
  draw(std::move(move));
}

void DrawnToolpath::draw(interp::Move move) {
  if (move.kind == interp::MoveKind::Dwell) return;
  if (extendLast(move)) return;
  closeLast();
  run_.assign(1, move.to);
  moves_.push_back(std::move(move));
  lastOpen_ = true;
  if (moves_.size() > maxMoves_) coarsen();
}

bool DrawnToolpath::extendLast(const interp::Move& move) {
  if (!lastOpen_ || !straight(move.kind) || run_.size() >= kRunPointsAtMost) return false;
  interp::Move& last = moves_.back();
  if (!straight(last.kind) || last.kind != move.kind || last.tool != move.tool || last.to != move.from) return false;
  for (const RZ& p : run_)
    if (distanceToSegment(p, last.from, move.to) > toleranceMm_) return false;
  last.to = move.to;
  run_.push_back(move.to);
  return true;
}

void DrawnToolpath::closeLast() {
  if (!lastOpen_) return;
  lastOpen_ = false;
  if (!drawn_.insert(keyOf(moves_.back())).second) moves_.pop_back();
}

DrawnToolpath::Key DrawnToolpath::keyOf(const interp::Move& move) const {
  const double cellMm = toleranceMm_ / 2;  // two points on one cell lie within tolerance/√2
  const auto cell = [&](double mm) { return static_cast<std::int64_t>(std::floor(mm / cellMm)); };
  const RZ centre = interp::isArc(move.kind) ? move.center : RZ(0, 0);
  return {static_cast<int>(move.kind),
          {cell(move.from.x()), cell(move.from.y()), cell(move.to.x()), cell(move.to.y()), cell(centre.x()), cell(centre.y())}};
}

void DrawnToolpath::coarsen() {
  while (moves_.size() > maxMoves_ / 2) {
    std::vector<interp::Move> kept = std::move(moves_);
    moves_.clear();
    drawn_.clear();
    lastOpen_ = false;
    toleranceMm_ *= 2;
    errorBoundMm_ += toleranceMm_;  // the new drawing strays this far from the one before
    for (interp::Move& move : kept) {
      if (!interp::isArc(move.kind)) {
        draw(std::move(move));
        continue;
      }
      // Arcs as chords within the tolerance, so that they merge and coarsen like the rest.
      const Arc arc(move.from, move.to, move.center, move.kind == interp::MoveKind::ArcCW);
      interp::Move chord = move;
      chord.kind = interp::MoveKind::Feed;
      for (const Arc& piece : arc.split(toleranceMm_)) {
        chord.from = piece.start();
        chord.to = piece.end();
        draw(chord);
      }
    }
  }
}

interp::Toolpath DrawnToolpath::toolpath(const interp::Toolpath& recorded) const {
  interp::Toolpath drawn;
  drawn.programName = recorded.programName;
  drawn.startPosition = recorded.startPosition;
  drawn.blockCount = recorded.blockCount;
  drawn.moves = moves_;
  const bool endsThere = !moves_.empty() && lastTaken_ && moves_.back().to == lastTaken_->to && moves_.back().tool == lastTaken_->tool;
  if (lastTaken_ && !endsThere) drawn.moves.push_back(*lastTaken_);
  return drawn;
}

}  // namespace lathesim::render
