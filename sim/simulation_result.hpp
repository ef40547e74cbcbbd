#pragma once
// What a simulation found (sim/simulate.hpp): the material each block removed, the crashes,
// the warnings, what parted off or fell loose, and the part.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/base/move.hpp"

namespace lathesim::sim {

class Stock;

/// A crash: something that must never touch the material or the chuck did.
struct Collision {
  int line = 0;
  int column = 0;
  std::string kind;  // "rapid_into_stock", "holder_into_stock", "into_chuck", "into_tailstock"
  double volumeMm3 = 0.0;
  int tool = 0;    // the tool of the move that collided
  RZ at{0, 0};     // where the tool stood (radius, Z) at the end of the block's first colliding
                   // move: where the machine would have stopped, the tool in what it hit
  std::uint16_t source = 0;  // the text line and column are in (interp::Toolpath::sources)
};

struct BlockRemoval {
  int block = 0;  // ordinal in the program
  int line = 0;
  int column = 0;
  double removedMm3 = 0.0;
  double timeS = 0.0;  // the machine time of the block's moves
  std::uint16_t source = 0;  // the text line and column are in (interp::Toolpath::sources)
};

/// Something the program does that a machine would let it do, but a machinist would not
/// want: cutting with the spindle stopped, a cycle started inside the material.
struct SimulationWarning {
  int line = 0;
  int column = 0;
  std::string message;
  std::uint16_t source = 0;  // the text line and column are in (interp::Toolpath::sources)
};

/// A cut that parted the bar: after it, some material no longer hung together with the
/// material at the chuck's end (Stock::takeLoosePieces), and fell.
struct PartOff {
  int line = 0;    // the block whose cut parted it
  int column = 0;
  double zMm = 0;  // Z of that cut's deepest point (its move ending nearest the axis, or past it)
  double volumeMm3 = 0;  // the piece that fell, measured on its level set
  std::optional<interp::PartsCatcherCommand> catcher;  // the parts catcher command in force, if any
  std::uint16_t source = 0;  // the text line and column are in (interp::Toolpath::sources)
};

/// A piece a cut set loose that the program did not part off on purpose (part_off.hpp): a skin,
/// a ring, a chip far smaller than what stays. It falls (or flies off), and is in no output
/// mesh; the part is still what the chuck holds.
struct LoosePiece {
  int line = 0;  // the block whose cut set it loose
  int column = 0;
  double volumeMm3 = 0;  // measured on its level set
  // Its extent in the meridian section (mm): radii and Z of its material.
  double rInnerMm = 0, rOuterMm = 0, zLowMm = 0, zHighMm = 0;
  double beyondMm3 = 0;  // the material that stays, at Z from the piece's lowest Z on
  std::uint16_t source = 0;  // the text line and column are in (interp::Toolpath::sources)
};

struct SimulationResult {
  std::vector<BlockRemoval> blocks;  // blocks that made moves (a dwell counts), in program order
  std::vector<Collision> collisions;
  std::vector<SimulationWarning> warnings;
  std::vector<PartOff> partOffs;     // in program order: the first piece is the part
  std::vector<LoosePiece> loosePieces;  // pieces set loose that are no part-off, in program order
  std::shared_ptr<const Stock> part;  // the first piece's level set, taken out of the stock; null
                                      // when nothing parted off (the stock is the part)
};

}  // namespace lathesim::sim
