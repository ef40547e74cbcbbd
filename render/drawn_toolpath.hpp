#pragma once
// The toolpath as part.png and report.html's 3D view draw it, built as the moves stream past
// and bounded in size whatever the program's length. A straight move that carries on the one
// before it (same kind and tool, from where it ended) is merged into it while every point of
// the run stays within the tolerance of the merged segment; a move drawn already (its ends,
// and an arc's centre, on the same cells of a grid half the tolerance wide) is drawn once;
// dwells, which stand still, are not drawn. A million blocks going back and forth over the
// same few paths keep a few moves; a finishing contour of short segments keeps one a pixel's
// fraction of curve. Past `maxMoves` the tolerance doubles and the moves kept are drawn again
// with it (arcs as chords), until at most half as many are left.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_set>
#include <vector>

#include "interp/base/move_sink.hpp"

namespace lathesim::render {

/// Drawn moves a picture holds at most (about 270 B each).
inline constexpr std::size_t kDrawnMovesAtMost = 20000;

class DrawnToolpath final : public interp::MoveSink {
 public:
  /// `toleranceMm` > 0: how far the drawn path may stray from the true one (a fraction of a
  /// pixel, in mm), while it holds no more than `maxMoves` moves.
  explicit DrawnToolpath(double toleranceMm, std::size_t maxMoves = kDrawnMovesAtMost);
  void take(interp::Move move) override;

  /// The moves to draw, in the order they came, the last move taken last (the pictures stand
  /// the tool at its end); the name, start position and block count are `recorded`'s.
  interp::Toolpath toolpath(const interp::Toolpath& recorded) const;
  /// How far (mm) any point of the drawn path may lie from the true path and the other way
  /// round: the tolerance asked for, or more once the size bound has coarsened it.
  double errorBoundMm() const { return errorBoundMm_; }
  std::size_t size() const { return moves_.size(); }

 private:
  struct Key {
    int kind;
    std::int64_t cells[6];  // from, to, centre (arcs only), each (radius, Z)
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const;
  };

  /// `move` into the drawing, without noting it as the last move taken.
  void draw(interp::Move move);
  /// Whether `move` could be merged into the last move kept (and was).
  bool extendLast(const interp::Move& move);
  /// The last move kept is final: dropped if it was drawn already.
  void closeLast();
  /// Doubles the tolerance until at most half of maxMoves_ are left.
  void coarsen();
  Key keyOf(const interp::Move& move) const;

  double toleranceMm_;
  double errorBoundMm_;
  std::size_t maxMoves_;
  std::vector<interp::Move> moves_;
  std::unordered_set<Key, KeyHash> drawn_;  // the keys of the moves kept, but the last while it is open
  bool lastOpen_ = false;                   // the last move kept is not in drawn_ yet
  std::vector<RZ> run_;                     // the true path's points along the last move kept, after its start
  std::optional<interp::Move> lastTaken_;
};

}  // namespace lathesim::render
