#include "sim/cut_history.hpp"

#include <limits>

#include "geometry/convex_overlap.hpp"

namespace lathesim::sim {
namespace {

double areaOf(const std::vector<ConvexPolygon>& pieces) {
  double area = 0.0;
  for (const ConvexPolygon& piece : pieces) area += piece.area();
  return area;
}

}  // namespace

std::optional<RevolvedRegion> CutHistory::changesOf(const std::vector<ConvexPolygon>& pieces) {
  bool bounded = true;
  std::vector<ConvexPolygon> changes;
  for (const ConvexPolygon& piece : pieces) {
    bounded &= piece.lowerBound().x() >= 0.0;
    if (bounded) {
      std::vector<ConvexPolygon> least{piece};
      double leastArea = piece.area();
      for (const ConvexPolygon& before : written_) {
        if (before.lowerBound().x() < 0.0) continue;  // its ψ counts its mirror image too
        std::vector<ConvexPolygon> left = differenceOf(piece, before);
        const double area = areaOf(left);
        if (area < leastArea) {
          leastArea = area;
          least = std::move(left);
        }
      }
      changes.insert(changes.end(), least.begin(), least.end());
    }
    written_.push_back(piece);
    if (written_.size() > kRemembered) written_.pop_front();
  }
  if (!bounded) return std::nullopt;
  return RevolvedRegion(changes);
}

}  // namespace lathesim::sim
