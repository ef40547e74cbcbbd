#pragma once
// Runs a toolpath through the stock: every move sweeps its tool's outline from start to end
// and removes what it covers — revolved about the spindle axis while the spindle turns, along
// the helix for a thread move (geometry/helical_sweep.hpp), and as a straight slot the
// insert's thickness wide when the spindle stands (geometry/straight_slot.hpp).

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/base/move.hpp"
#include "sim/holder_check.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {

/// A crash: something that must never touch the material or the chuck did.
struct Collision {
  int line = 0;
  int column = 0;
  std::string kind;  // "rapid_into_stock", "holder_into_stock", "into_chuck"
  double volumeMm3 = 0.0;
  int tool = 0;    // the tool of the move that collided
  RZ at{0, 0};     // where the tool stood (radius, Z) at the end of the block's first colliding
                   // move: where the machine would have stopped, the tool in what it hit
};

struct BlockRemoval {
  int block = 0;  // ordinal in the program
  int line = 0;
  int column = 0;
  double removedMm3 = 0.0;
  double timeS = 0.0;  // the machine time of the block's moves
};

/// Something the program does that a machine would let it do, but a machinist would not
/// want: cutting with the spindle stopped, a cycle started inside the material.
struct SimulationWarning {
  int line = 0;
  int column = 0;
  std::string message;
};

/// A cut that parted the bar: after it, some material no longer hung together with the
/// material at the chuck's end (Stock::takeLoosePieces), and fell.
struct PartOff {
  int line = 0;    // the block whose cut parted it
  int column = 0;
  double zMm = 0;  // Z of that cut's deepest point (its move ending nearest the axis, or past it)
  double volumeMm3 = 0;  // the piece that fell, measured on its level set
  std::optional<interp::PartsCatcherCommand> catcher;  // the parts catcher command in force, if any
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

/// Adds a collision, or grows the block's own (same line and column) of the same kind when the
/// block's are the last ones: one collision for the two legs of a dog-leg rapid, or for the
/// moves of one cycle.
void recordCollision(std::vector<Collision>& collisions, const interp::Move& move, const char* kind, double volumeMm3);

/// A rapid that removes more than this many voxels' worth of material is a collision;
/// below it, the removal is rounding at a surface the rapid merely grazes.
inline constexpr double kCollisionVoxels = 10.0;

/// A cycle start point deeper in the material than this many voxels is inside the stock
/// (one voxel: points on the surface, such as a corner just cut, are not).
inline constexpr double kInsideStockVoxels = 1.0;

using ToolOutlines = std::map<int, ConvexPolygon>;  // tool number → outline (radial, axial) mm
/// tool number → the insert's thickness across the tool's plane (mm): what a cut with the
/// spindle stopped removes across that plane. A tool not listed is kDefaultInsertThicknessMm.
using ToolThicknesses = std::map<int, double>;
inline constexpr double kDefaultInsertThicknessMm = 4.0;
using BlockProgress = std::function<void(int blocksDone, int blocksTotal)>;

/// Called before the moves [firstMove, endMove) are cut, with the stock as it stands then and
/// the collisions found so far: what a picture taken while those moves run shows (the
/// animation's frames, the crashes marked from the frame after each).
using CutObserver = std::function<void(std::size_t firstMove, std::size_t endMove, const Stock& stock,
                                       const std::vector<Collision>& collisions)>;

/// Removes every move's swept region from `stock` in program order. Consecutive feeds and
/// arcs of one block made with the spindle turning are united, revolved, and written once (a
/// cycle's cut and retract overlap heavily); each rapid is written on its own so that a rapid
/// into material is caught and located; each thread move on its own along its helix (from
/// its start angle, one turn per lead); each feed, arc or thread move made with the spindle
/// stopped (before M03/M04, after M05, at S0) as a straight slot at the angle the spindle
/// stands at (Move::spindleAngleDeg; arcs by their chords); dwells remove nothing. After each
/// write that removed material, what came loose is taken out of `stock` (part_off.hpp): the
/// stock is then the stub left in the chuck, and the first piece is the result's `part`.
SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress = {});

/// The same, and each move is also checked for holder and chuck collisions (holder_check.hpp)
/// when `checks` is given.
SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks);

/// The same, with the tools' insert thicknesses for cuts made with the spindle stopped, and
/// telling `observer` (if set) of each group of moves before it is cut.
SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks,
                          const ToolThicknesses& thicknesses, const CutObserver& observer = {});

/// Whether the spindle turns during `move` (M03/M04 in force and S > 0).
bool spindleTurns(const interp::Move& move);

}  // namespace lathesim::sim
