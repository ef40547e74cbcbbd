#pragma once
// A binary STL as written, read back byte by byte and checked without the library's own mesh
// code: is it closed and consistently oriented, and what volume does it enclose.

#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lathesim::test {

using StlVertex = std::array<float, 3>;
using StlTriangle = std::array<StlVertex, 3>;

/// The triangles of a binary STL's bytes; empty when the size does not match the count.
inline std::vector<StlTriangle> readBinaryStl(const std::string& bytes) {
  if (bytes.size() < 84) return {};
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() != 84u + 50u * static_cast<std::size_t>(count)) return {};
  std::vector<StlTriangle> triangles(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(i) + 12;  // past the normal
    for (int v = 0; v < 3; ++v) std::memcpy(triangles[i][v].data(), facet + 12 * v, 12);
  }
  return triangles;
}

struct StlFacts {
  int degenerate = 0;  // triangles with two corners at one point
  int badEdges = 0;    // directed edges not matched by exactly one opposite edge
  std::size_t directedEdges = 0;
  double volumeMm3 = 0;  // enclosed, by the divergence theorem
};

/// Welds the vertices by exact position (as an STL reader does), then every undirected edge must
/// be used by exactly two triangles, once in each direction: closed and consistently oriented.
/// V = Σ v0 · (v1 × v2) / 6 over outward-oriented triangles.
inline StlFacts factsOf(const std::vector<StlTriangle>& triangles) {
  StlFacts facts;
  std::map<StlVertex, int> ids;
  const auto id = [&](const StlVertex& v) { return ids.emplace(v, static_cast<int>(ids.size())).first->second; };
  std::map<std::pair<int, int>, int> directed;
  for (const StlTriangle& t : triangles) {
    const std::array<int, 3> v{id(t[0]), id(t[1]), id(t[2])};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) ++facts.degenerate;
    for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
    const auto& a = t[0];
    const auto& b = t[1];
    const auto& c = t[2];
    const double cx = double(b[1]) * c[2] - double(b[2]) * c[1];
    const double cy = double(b[2]) * c[0] - double(b[0]) * c[2];
    const double cz = double(b[0]) * c[1] - double(b[1]) * c[0];
    facts.volumeMm3 += (a[0] * cx + a[1] * cy + a[2] * cz) / 6.0;
  }
  facts.directedEdges = directed.size();
  for (const auto& [edge, uses] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (uses != 1 || reverse == directed.end() || reverse->second != 1) ++facts.badEdges;
  }
  return facts;
}

}  // namespace lathesim::test
