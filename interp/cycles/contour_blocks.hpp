#pragma once
// The contour blocks N(ns)…N(nf) of G70–G73 (`P(ns) Q(nf)`), found in the program and run.
// Rules (lathe-cycles.md §3, GSK980TDi 3.23): P and Q both given; both N numbers in the same
// program as the cycle block, nf not before ns; at most 200 blocks; no N twice; only G00–G03,
// G04, G96/G97, G98/G99 and G40–G42 among them, no M98/M99 (nor M02/M30); the ns block holds
// G00 or G01. Each violation is an error at the word or block at fault.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "interp/execution/block_executor.hpp"
#include "interp/contour/contour.hpp"
#include "interp/interpreter.hpp"
#include "interp/text/lexer.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/text/program.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

constexpr int kMaxContourBlocks = 200;  // GSK980TDi: at most 200 blocks from ns to nf

/// Ordinals (Program::block) of the ns and nf blocks. An ns block that holds nothing but
/// its N number (`N01;`) is a label: the contour then starts at the block after it, which
/// must hold G00 or G01 as an ns block does.
struct ContourSpan {
  std::size_t first = 0;
  std::size_t last = 0;
  std::size_t start = 0;  // the block that opens the contour: `first`, or the one after a label
};

/// The cycle block asking for a contour.
struct ContourRequest {
  std::string_view cycle;  // "G71" …
  std::optional<Word> p;   // P(ns)
  std::optional<Word> q;   // Q(nf)
  int line = 0;            // of the cycle block
  int column = 0;          // of the cycle's code
};

/// Finds and checks the contour of the cycle in block `cycle.index`. Macro blocks among them
/// are read with the variables as they are now, under `state` (for G20) and the options'
/// dialect; a macro statement in the contour is an error.
Result<ContourSpan> findContourBlocks(const BlockPlace& cycle, const ContourRequest& request,
                                      const ModalState& state, const InterpreterOptions& options);

/// The contour as G71–G73 see it, run from `state.position` (A) on a copy of the state.
struct ExtractedContour {
  Contour contour;
  std::vector<NoseComp> noseComps;     // the G41/G42 in force in each segment's block
  std::size_t firstBlockSegments = 0;  // how many segments (0 or 1) the ns block made
  bool firstBlockRapid = false;        // the ns block is G00 (else G01)
  bool firstBlockHasX = false;         // the ns block gives X or U
  bool firstBlockHasZ = false;         // the ns block gives Z or W
};

/// Runs the span's blocks through the block executor from `state`; their moves, dwells left
/// out, become the contour, each segment located at its block. Nothing of the state is kept.
Result<ExtractedContour> extractContour(const BlockPlace& cycle, ContourSpan span,
                                        const ModalState& state,
                                        const InterpreterOptions& options);

/// G70: runs the span's blocks as written from `state`. The moves carry their own blocks'
/// lines; the state is the one after the last block.
Result<BlockOutcome> runContourBlocks(const BlockPlace& cycle, ContourSpan span,
                                      ModalState state, const InterpreterOptions& options);

}  // namespace lathesim::interp
