// Random face, turn, groove and peck programs on random bars, each block's removal checked
// against the exact volume of what it cut (Pappus, worked out below independently of the
// level set), and the level set's volume against its own mesh.
//
// The tool is a rectangle and every move runs along an axis, so each move sweeps a
// rectangle of the (r, z) half-plane and what a program leaves is the bar minus a union of
// rectangles: exact on a grid of the rectangles' own edges. A face pass below the face
// followed by a retract along the axis cuts a ring loose: it falls (part-off), so the grid's
// cells are joined across their shared edges after every write, and what no longer hangs
// together with the bar's left end is gone from then on. Cut positions lie on a lattice
// (pitch 2–3.5 voxels, at an arbitrary phase to the voxels, anchored at the bar's face and
// rim), so the cuts meet each other's faces exactly — face passes repeated at the same Z,
// a pass ending where the last began, pecks retracing their plunge, a face pass at the
// bar's own face (the "ghost sheet" cases) — and never leave a wall or slot thinner than
// two voxels, which the grid cannot resolve. The bar's faces are placed around 128-voxel
// block boundaries, where issue 10 lost whole blocks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "interp/base/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {
namespace {

// A rectangle of the (r, z) half-plane; revolved, a ring or a disc.
struct Box {
  double r0, r1, z0, z1;
};

/// The exact solid a program leaves: the bar minus the union of the boxes its moves swept,
/// on the grid of all their edges. A box's index is the order it was cut in.
class RevolvedBoxes {
 public:
  RevolvedBoxes(const StockSpec& bar, const std::vector<Box>& boxes) {
    const double radius = bar.diameterMm / 2.0;
    rs_ = {0.0, radius};
    zs_ = {bar.faceZMm - bar.lengthMm, bar.faceZMm};
    for (const Box& b : boxes) {
      rs_.insert(rs_.end(), {std::min(b.r0, radius), std::min(b.r1, radius)});
      zs_.insert(zs_.end(), {std::clamp(b.z0, zs_[0], zs_[1]), std::clamp(b.z1, zs_[0], zs_[1])});
    }
    // Edges the program puts at one place may differ in the last bits (a plunge's Z plus the
    // tool's width against a lattice Z): one edge, or a cell of no thickness would join, or
    // part, the pieces on either side of it.
    for (auto* axis : {&rs_, &zs_}) {
      std::sort(axis->begin(), axis->end());
      axis->erase(std::unique(axis->begin(), axis->end(), [](double a, double b) { return b - a < 1e-9; }), axis->end());
    }
    // The first box that covers each cell (boxes.size() when none does): boxes in reverse
    // order, each over the cells between its edges.
    firstCut_.assign(cells(), static_cast<int>(boxes.size()));
    fallen_.assign(cells(), 0);
    const auto cellsBetween = [](const std::vector<double>& edges, double lo, double hi) {
      return std::pair(std::lower_bound(edges.begin(), edges.end(), lo - 1e-9) - edges.begin(),
                       std::lower_bound(edges.begin(), edges.end(), hi - 1e-9) - edges.begin());
    };
    for (int k = static_cast<int>(boxes.size()) - 1; k >= 0; --k) {
      const Box& b = boxes[k];
      const auto [i0, i1] = cellsBetween(rs_, b.r0, std::min(b.r1, rs_.back()));
      const auto [j0, j1] = cellsBetween(zs_, std::max(b.z0, zs_.front()), std::min(b.z1, zs_.back()));
      for (auto i = i0; i < i1; ++i)
        for (auto j = j0; j < j1; ++j) firstCut_[index(static_cast<int>(i), static_cast<int>(j))] = k;
    }
  }

  struct Solid {
    double volumeMm3 = 0;
    double surfaceMm2 = 0;
  };
  /// A piece that fell, with the material held in the chuck from its lowest Z on: the piece is
  /// a part-off only when it holds more than that (sim/part_off.cpp), else a loose piece.
  struct Fallen : Solid {
    Solid heldBeyond;
  };

  /// What is left once the first `cutBoxes` boxes are cut (and what fell has gone).
  Solid left(int cutBoxes) const {
    return measure([&](int cell) { return !fallen_[cell] && firstCut_[cell] >= cutBoxes; });
  }
  /// What boxes [from, to) remove, given boxes [0, from) are already cut.
  Solid removed(int from, int to) const {
    return measure([&](int cell) { return !fallen_[cell] && firstCut_[cell] >= from && firstCut_[cell] < to; });
  }

  /// Once the first `cutBoxes` boxes are cut: the pieces of what is left that no longer share
  /// an edge, through each other, with the cells at the bar's left end (never cut). They fall:
  /// gone from left() and removed() from then on. A piece thinner than `crumbMm` (twice its
  /// volume over its area, as for the mesh's crumbs) is no part the grid could hold — a sliver
  /// between two plunges whose step the program rounded — and stays.
  std::vector<Fallen> fall(int cutBoxes, double crumbMm) {
    const int nr = static_cast<int>(rs_.size()) - 1, nz = static_cast<int>(zs_.size()) - 1;
    const auto material = [&](int i, int j) {
      return i >= 0 && i < nr && j >= 0 && j < nz && !fallen_[index(i, j)] && firstCut_[index(i, j)] >= cutBoxes;
    };
    std::vector<int> piece(cells(), -1);
    std::vector<int> stack;
    int pieces = 0;
    std::vector<bool> held;
    for (int i0 = 0; i0 < nr; ++i0)
      for (int j0 = 0; j0 < nz; ++j0) {
        if (!material(i0, j0) || piece[index(i0, j0)] >= 0) continue;
        held.push_back(false);
        stack.assign(1, index(i0, j0));
        piece[index(i0, j0)] = pieces;
        while (!stack.empty()) {
          const int cell = stack.back();
          stack.pop_back();
          const int i = cell / nz, j = cell % nz;
          held.back() = held.back() || j == 0;
          for (const auto& [di, dj] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}})
            if (material(i + di, j + dj) && piece[index(i + di, j + dj)] < 0) {
              piece[index(i + di, j + dj)] = pieces;
              stack.push_back(index(i + di, j + dj));
            }
        }
        ++pieces;
      }
    std::vector<Fallen> fell;
    for (int p = 0; p < pieces; ++p) {
      if (held[p]) continue;
      Fallen fallen;
      static_cast<Solid&>(fallen) = measure([&](int cell) { return piece[cell] == p; });
      if (2.0 * fallen.volumeMm3 / fallen.surfaceMm2 < crumbMm) continue;
      int lowest = nz;
      for (int cell = 0; cell < cells(); ++cell)
        if (piece[cell] == p) lowest = std::min(lowest, cell % nz);
      fallen.heldBeyond = measure([&](int cell) { return piece[cell] >= 0 && held[piece[cell]] && cell % nz >= lowest; });
      fell.push_back(fallen);
      for (int cell = 0; cell < cells(); ++cell)
        if (piece[cell] == p) fallen_[cell] = 1;
    }
    return fell;
  }

  /// The length (mm) of the part's edges — circles through the corners of its section —
  /// that lie within `reachMm` of one of `boxes`, once the first `cutBoxes` are cut.
  double edgeLengthNear(int cutBoxes, const std::vector<Box>& boxes, double reachMm) const {
    const int nr = static_cast<int>(rs_.size()) - 1, nz = static_cast<int>(zs_.size()) - 1;
    const auto in = [&](int i, int j) {
      return i >= 0 && i < nr && j >= 0 && j < nz && !fallen_[index(i, j)] && firstCut_[index(i, j)] >= cutBoxes;
    };
    double length = 0.0;
    for (int i = 1; i <= nr; ++i)  // corners on the axis are points
      for (int j = 0; j <= nz; ++j) {
        const bool a = in(i - 1, j - 1), b = in(i, j - 1), c = in(i - 1, j), d = in(i, j);
        const int inside = a + b + c + d;
        if (!(inside == 1 || inside == 3 || (inside == 2 && a == d))) continue;  // no corner here
        const double r = rs_[i], z = zs_[j];
        const bool near = std::any_of(boxes.begin(), boxes.end(), [&](const Box& box) {
          return r > box.r0 - reachMm && r < box.r1 + reachMm && z > box.z0 - reachMm && z < box.z1 + reachMm;
        });
        if (near) length += 2.0 * M_PI * r;
      }
    return length;
  }

 private:
  int cells() const { return static_cast<int>((rs_.size() - 1) * (zs_.size() - 1)); }
  int index(int i, int j) const { return i * static_cast<int>(zs_.size() - 1) + j; }

  template <typename InSolid>
  Solid measure(const InSolid& inSolid) const {
    const int nr = static_cast<int>(rs_.size()) - 1, nz = static_cast<int>(zs_.size()) - 1;
    const auto in = [&](int i, int j) { return i >= 0 && i < nr && j >= 0 && j < nz && inSolid(index(i, j)); };
    Solid solid;
    for (int i = 0; i < nr; ++i)
      for (int j = 0; j < nz; ++j) {
        if (!in(i, j)) continue;
        const double annulus = M_PI * (rs_[i + 1] * rs_[i + 1] - rs_[i] * rs_[i]), height = zs_[j + 1] - zs_[j];
        solid.volumeMm3 += annulus * height;
        solid.surfaceMm2 += annulus * (!in(i, j - 1) + !in(i, j + 1));
        solid.surfaceMm2 += 2.0 * M_PI * height * (rs_[i + 1] * !in(i + 1, j) + (i > 0 ? rs_[i] * !in(i - 1, j) : 0.0));
      }
    return solid;
  }

  std::vector<double> rs_, zs_;
  std::vector<int> firstCut_;
  std::vector<char> fallen_;  // per cell: part of a piece that fell
};

/// The box a straight axis-parallel move of a rectangular tool [0, wr] × [0, wz] sweeps,
/// revolved (a tool reaching across the axis revolves with its mirror image).
Box sweptBox(const interp::Move& move, double wr, double wz) {
  const double a = std::min(move.from.x(), move.to.x()), b = std::max(move.from.x(), move.to.x()) + wr;
  const double inner = a < 0.0 && b > 0.0 ? 0.0 : std::min(std::abs(a), std::abs(b));
  return {inner, std::max(std::abs(a), std::abs(b)), std::min(move.from.y(), move.to.y()),
          std::max(move.from.y(), move.to.y()) + wz};
}

// ---- random programs ---------------------------------------------------------------------

struct Program {
  StockSpec bar;
  double voxelMm = 0;
  double toolRadialMm = 0, toolAxialMm = 0;  // the rectangle tool [0, wr] × [0, wz]
  RZ home;                                   // start and return point, clear of the bar
  std::string text;
};

std::string cutFixed4(double v) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(4);
  out << (std::abs(v) < 5e-5 ? 0.0 : v);
  return out.str();
}

// Values on a 0.0001 mm grid, as a program writes them, so that lattice positions printed
// in different blocks are the same number.
double onProgramGrid(double mm) { return std::round(mm * 1e4) / 1e4; }

class ProgramMaker {
 public:
  explicit ProgramMaker(std::uint32_t seed) : seed_(seed), random_(seed) {}

  Program make() {
    Program p;
    // Every other bar holds whole 128³ interior blocks: 380–450 voxels across (to 800, Φ400,
    // at 0.5 mm) and 150–200 long; the others are smaller (100–380 across). Build and cut
    // times follow the bar's surface in voxels.
    static const double kVoxelsMm[] = {0.05, 0.1, 0.2, 0.5};
    const double h = p.voxelMm = kVoxelsMm[pick(0, 3)];
    const double pitch = onProgramGrid(h * uniform(2.0, 3.5));  // lattice pitch
    const bool holdsBlocks = seed_ % 2 == 0;
    const double across = holdsBlocks ? uniform(380.0, h == 0.5 ? 800.0 : 450.0) : uniform(100.0, 380.0);
    const double diameter = onProgramGrid(h * across);
    const int lengthSteps = holdsBlocks ? static_cast<int>(uniform(150.0, 200.0) * h / pitch) : pick(8, 40);
    const double length = onProgramGrid(std::max(lengthSteps * pitch + uniform(0.0, pitch), 20.5 * h));
    // The face from 2 voxels below a block boundary (−1, 0 or 1 blocks of 128) to 5 above,
    // spread evenly over the pairs of seeds (golden-ratio steps) rather than at random, so
    // that a few bars of each kind cover the whole range.
    const double offsetVoxels = -2.0 + 7.0 * std::fmod((seed_ / 2) * 0.6180339887498949, 1.0);
    const double face = onProgramGrid((128.0 * pick(-1, 1) + offsetVoxels) * h);
    p.bar = {diameter, length, face};
    const double radius = diameter / 2.0;

    const int toolSteps = pick(2, 4);
    p.toolRadialMm = p.toolAxialMm = toolSteps * pitch;
    p.home = {onProgramGrid(radius + p.toolRadialMm + 5.0), onProgramGrid(face + p.toolAxialMm + 5.0)};
    const double clearR = onProgramGrid(radius + 2.0), clearZ = p.home.y();

    // Lattice positions: radii R − k·pitch down to the axis, Z face − k·pitch down the bar.
    const int radialSteps = static_cast<int>((radius - 2.0 * pitch) / pitch);
    const int axialSteps = std::min(lengthSteps, static_cast<int>(length / pitch)) - 1;
    const auto latticeR = [&](int k) { return onProgramGrid(radius - k * pitch); };
    const auto latticeZ = [&](int k) { return onProgramGrid(face - k * pitch); };

    std::ostringstream g;
    g << "G99 G97 S800 M03\nG00 X" << cutFixed4(2 * p.home.x()) << " Z" << cutFixed4(p.home.y()) << "\n";
    const auto home = [&] { g << "G00 X" << cutFixed4(2 * p.home.x()) << "\nG00 Z" << cutFixed4(clearZ) << "\n"; };
    std::string previous;
    const int cuts = pick(4, 9);
    for (int c = 0; c < cuts; ++c) {
      std::ostringstream cut;
      if (!previous.empty() && pick(0, 3) == 0) {  // the same cut again, at the same place
        g << previous;
        home();
        continue;
      }
      // One cut in three at the bar's own face or rim (k = 0): the tool's edge on it.
      const int kr = pick(0, 2) == 0 ? 0 : pick(1, std::max(1, radialSteps));
      const int kz = pick(0, 2) == 0 ? 0 : pick(1, axialSteps);
      switch (pick(0, 5)) {
        case 0:  // face pass (G01) to a radius or past the axis, then up and out
          cut << "G00 Z" << cutFixed4(latticeZ(kz)) << "\nG00 X" << cutFixed4(2 * clearR) << "\nG01 X"
              << cutFixed4(pick(0, 1) ? -p.toolRadialMm : 2 * latticeR(kr)) << " F0.2\nG01 Z" << cutFixed4(clearZ) << "\n";
          break;
        case 1:  // G94 face cycle, once or twice at the same Z
          cut << "G00 X" << cutFixed4(2 * clearR) << " Z" << cutFixed4(clearZ) << "\nG94 X" << cutFixed4(2 * latticeR(kr))
              << " Z" << cutFixed4(latticeZ(kz)) << " F0.2\n";
          if (pick(0, 1)) cut << "X" << cutFixed4(2 * latticeR(kr)) << "\n";
          break;
        case 2:  // turning pass (G01) down to a Z, then out
          cut << "G00 X" << cutFixed4(2 * latticeR(kr)) << " Z" << cutFixed4(clearZ) << "\nG01 Z" << cutFixed4(latticeZ(kz))
              << " F0.2\nG01 X" << cutFixed4(2 * clearR) << "\n";
          break;
        case 3:  // G90 turning cycle
          cut << "G00 X" << cutFixed4(2 * clearR) << " Z" << cutFixed4(clearZ) << "\nG90 X" << cutFixed4(2 * latticeR(kr))
              << " Z" << cutFixed4(latticeZ(kz)) << " F0.2\n";
          break;
        case 4: {  // G75 groove, at most 10 steps deep: pecks to the bottom, shifts along Z
          const int kzEnd = std::max(1, kz);
          const int depth = std::min(kr, 10);
          const int width = pick(0, 3);
          const double peck = onProgramGrid(uniform(0.3, 1.0) * p.toolRadialMm);
          cut << "G00 Z" << cutFixed4(latticeZ(kzEnd + width)) << "\nG00 X" << cutFixed4(2 * clearR) << "\nG75 R"
              << cutFixed4(0.5 * peck) << "\nG75 X" << cutFixed4(2 * latticeR(depth)) << " Z" << cutFixed4(latticeZ(kzEnd))
              << " P" << std::lround(2000 * peck) << " Q" << std::lround(1000 * p.toolAxialMm) << " F0.05\n";
          break;
        }
        default: {  // G74 pecks on the axis, into the face
          const double peck = onProgramGrid(uniform(0.5, 2.0) * p.toolAxialMm);
          cut << "G00 X0 Z" << cutFixed4(clearZ) << "\nG74 R" << cutFixed4(0.5 * peck) << "\nG74 Z"
              << cutFixed4(latticeZ(std::max(1, kz))) << " Q" << std::lround(1000 * peck) << " F0.1\n";
          break;
        }
      }
      previous = cut.str();
      g << previous;
      home();
    }
    g << "M30\n";
    p.text = g.str();
    return p;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }
  std::uint32_t seed_;
  std::mt19937 random_;
};

// ---- the sweep ---------------------------------------------------------------------------

constexpr std::uint32_t kSeed = 20261124;
constexpr int kPrograms = 12;

TEST(CutVolume, EveryBlockRemovesItsExactVolumeAndTheMeshAgrees) {
  for (int n = 0; n < kPrograms; ++n) {
    const std::uint32_t seed = kSeed + n;
    const Program program = ProgramMaker(seed).make();
    const double h = program.voxelMm;
    SCOPED_TRACE(testing::Message() << "seed " << seed << ": Φ" << program.bar.diameterMm << "×"
                                    << program.bar.lengthMm << " face Z" << program.bar.faceZMm << " at " << h
                                    << " mm, tool " << program.toolRadialMm << " mm square, program:\n"
                                    << program.text);
    interp::InterpreterOptions options;
    options.startPosition = program.home;
    options.toolNumbers = {1};
    const interp::InterpretResult interpreted = interp::interpret(program.text, "random.nc", options);
    ASSERT_TRUE(interpreted.ok()) << interp::format(interpreted.diagnostics.front());
    const std::vector<RZ> rectangle{
        {0, 0}, {program.toolRadialMm, 0}, {program.toolRadialMm, program.toolAxialMm}, {0, program.toolAxialMm}};
    ToolOutlines tools;
    tools.emplace(1, *ConvexPolygon::fromOutline(rectangle).polygon);

    std::vector<Box> boxes;
    std::vector<int> boxesAfterBlock;  // per block ordinal: how many boxes are cut once it has run
    // Where sim writes (simulate.hpp): a block's consecutive feeds together, each rapid alone.
    // After each write, what came loose falls: how many boxes are cut then, per block.
    std::vector<std::vector<int>> writesOfBlock;
    const auto& moves = interpreted.toolpath.moves;
    for (std::size_t m = 0; m < moves.size(); ++m) {
      const interp::Move& move = moves[m];
      ASSERT_TRUE(std::abs(move.from.x() - move.to.x()) < 1e-9 || std::abs(move.from.y() - move.to.y()) < 1e-9)
          << "line " << move.line << " is not along an axis";
      boxes.push_back(sweptBox(move, program.toolRadialMm, program.toolAxialMm));
      boxesAfterBlock.resize(move.block + 1, boxesAfterBlock.empty() ? 0 : boxesAfterBlock.back());
      boxesAfterBlock[move.block] = static_cast<int>(boxes.size());
      writesOfBlock.resize(move.block + 1);
      const bool writtenWithNext = m + 1 < moves.size() && moves[m + 1].block == move.block &&
                                   interp::isCutting(move.kind) && interp::isCutting(moves[m + 1].kind);
      if (!writtenWithNext) writesOfBlock[move.block].push_back(static_cast<int>(boxes.size()));
    }
    RevolvedBoxes exact(program.bar, boxes);

    Stock stock(program.bar, h);
    const RevolvedBoxes::Solid bar = exact.left(0);
    EXPECT_NEAR(stock.volumeMm3(), bar.volumeMm3, volumeToleranceMm3(bar.surfaceMm2, h));
    const SimulationResult result = simulate(interpreted.toolpath, tools, stock);
    int cutBefore = 0;
    std::size_t partOffs = 0, loosePieces = 0;
    for (const BlockRemoval& block : result.blocks) {
      const int cutAfter = boxesAfterBlock[block.block];
      for (const int cut : writesOfBlock[block.block])
        for (const RevolvedBoxes::Fallen& piece : exact.fall(cut, h)) {
          // A part-off when the piece holds most of the material from its lowest Z on; where
          // the two are nearer than the grid can tell, either reading is right.
          const double margin = volumeToleranceMm3(piece.surfaceMm2 + piece.heldBeyond.surfaceMm2, h);
          const bool partOff = piece.volumeMm3 > piece.heldBeyond.volumeMm3;
          const bool eitherWay = std::abs(piece.volumeMm3 - piece.heldBeyond.volumeMm3) < margin;
          const bool seenAsPartOff = partOffs < result.partOffs.size() && result.partOffs[partOffs].line == block.line;
          const bool seenAsLoose =
              loosePieces < result.loosePieces.size() && result.loosePieces[loosePieces].line == block.line;
          const double* seenVolume = nullptr;
          if (seenAsPartOff && (partOff || eitherWay)) {
            seenVolume = &result.partOffs[partOffs++].volumeMm3;
          } else if (seenAsLoose && (!partOff || eitherWay)) {
            seenVolume = &result.loosePieces[loosePieces++].volumeMm3;
          }
          ASSERT_NE(seenVolume, nullptr) << "line " << block.line << " sets " << piece.volumeMm3 << " mm³ loose ("
                                         << piece.heldBeyond.volumeMm3 << " mm³ held beyond it: "
                                         << (partOff ? "a part-off" : "a loose piece") << "), which sim does not see";
          EXPECT_NEAR(*seenVolume, piece.volumeMm3, volumeToleranceMm3(piece.surfaceMm2, h)) << "line " << block.line;
        }
      const RevolvedBoxes::Solid removed = exact.removed(cutBefore, cutAfter);
      // Next to an edge of the part the level set is only a bound on the distance (the max
      // of the cuts' distances; sweep-math.md): the row of air voxels along an edge may
      // hold φ below the true distance (at most h/2 where it counts), so a later cut that
      // passes within a voxel may change what they count without removing anything — at
      // most half a voxel in each, one row: h²/2 per millimetre of edge (0.17 h² seen).
      // Away from edges, a block that cuts nothing must measure nothing.
      const std::vector<Box> blockBoxes(boxes.begin() + cutBefore, boxes.begin() + cutAfter);
      const double edgeAllowance = 0.5 * h * h * exact.edgeLengthNear(cutBefore, blockBoxes, h);
      EXPECT_NEAR(block.removedMm3, removed.volumeMm3, volumeToleranceMm3(removed.surfaceMm2, h) + edgeAllowance)
          << "line " << block.line;
      cutBefore = cutAfter;
    }
    EXPECT_EQ(result.partOffs.size(), partOffs);
    EXPECT_EQ(result.loosePieces.size(), loosePieces);
    const RevolvedBoxes::Solid part = exact.left(static_cast<int>(boxes.size()));
    const double tolerance = volumeToleranceMm3(part.surfaceMm2, h);
    const double levelSet = stock.volumeMm3();
    EXPECT_NEAR(levelSet, part.volumeMm3, tolerance);
    TriangleMesh mesh = stock.mesh(0.002);
    weldCoincidentVertices(mesh);  // as the STL will be read
    EXPECT_TRUE(isClosedAndOriented(mesh));
    EXPECT_NEAR(enclosedVolumeMm3(mesh), levelSet, tolerance);
    if (HasFailure()) return;  // one program's story is enough to read
  }
}

}  // namespace
}  // namespace lathesim::sim
