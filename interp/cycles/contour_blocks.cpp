#include "interp/cycles/contour_blocks.hpp"

#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/cycles/sorted_words.hpp"
#include "interp/motion/corners.hpp"
#include "interp/text/label_number.hpp"

namespace lathesim::interp {
namespace {

bool allowedInContour(GGroup group, int number) {
  switch (group) {
    case GGroup::Motion: return number <= 3;    // G00–G03
    case GGroup::NonModal: return number == 4;  // G04
    case GGroup::SpindleMode:                   // G96 G97
    case GGroup::FeedMode:                      // G98 G99
    case GGroup::NoseRadius:                    // G40 G41 G42
    case GGroup::Distance: return true;         // G90/G91 of the dialects that have them
    case GGroup::Plane:
    case GGroup::Units:
    case GGroup::WorkCoordinates:
    case GGroup::DrillingCycle: return false;
  }
  return false;
}

std::string spanName(const Program& program, ContourSpan span) {
  return fmt::format("N{}–N{}", *program.block(span.first).sequenceNumber,
                     *program.block(span.last).sequenceNumber);
}

// One block of the span against the rules; `first` is whether it is the ns block.
Status checkContourBlock(const ParsedBlock& block, bool first, std::string_view cycle,
                         const std::string& span) {
  for (const auto& [group, code] : block.gCodes) {
    if (!allowedInContour(group, code.number)) {
      return Error{block.line, code.column,
                   fmt::format("{} is not allowed in the contour of {} ({}): only G00–G03, G04, "
                               "G96/G97, G98/G99 and G40–G42",
                               code.text, cycle, span)};
    }
  }
  for (MGroup group : {MGroup::Subprogram, MGroup::ProgramEnd}) {
    if (const auto code = block.mCode(group)) {
      return Error{block.line, code->column,
                   fmt::format("{} is not allowed in the contour of {} ({}): the contour must "
                               "not call, return or end",
                               code->text, cycle, span)};
    }
  }
  if (first) {
    const auto motion = block.gCode(GGroup::Motion);
    if (!motion || motion->number > 1) {
      return Error{block.line, motion ? motion->column : block.column,
                   fmt::format("the first block of the contour of {} ({}) must hold G00 or G01{}",
                               cycle, span,
                               motion ? fmt::format(", not {}", motion->text) : std::string())};
    }
  }
  return success();
}

Result<std::size_t> findSequence(const Program& program, std::size_t cycleIndex,
                                 const ContourRequest& request, const Word& word) {
  auto read = labelNumberOf(word, request.line, kMaxSequenceDigits, "a sequence number (e.g. P10 for N10)");
  if (!read.ok()) return read.error();
  const int number = read.value();
  const SequenceBlocks found = program.findSequence(number, cycleIndex);
  if (found.count == 0) {
    return Error{request.line, word.column,
                 fmt::format("{} {}: there is no block N{} in this program", request.cycle,
                             word.text(), number)};
  }
  // GSK980TDi §3.23.1 note 14: cycles in one program give their contours their own numbers.
  if (found.count > 1) {
    return Error{request.line, word.column,
                 fmt::format("{} {}: N{} numbers two blocks, on lines {} and {}; the contours of the compound "
                             "cycles in one program need N numbers of their own",
                             request.cycle, word.text(), number, program.block(found.first).line,
                             program.block(found.second).line)};
  }
  return found.first;
}

// A block that holds its N number and nothing else.
bool isLabelOnly(const Program& program, const ProgramBlock& block) {
  const auto parsed = program.plainWords(block);
  return parsed && parsed->gCodes.empty() && parsed->mCodes.empty() && parsed->words.size() == 1 &&
         parsed->has('N');
}

}  // namespace

Result<ContourSpan> findContourBlocks(const BlockPlace& cycle, const ContourRequest& request,
                                      const ModalState& state, const InterpreterOptions& options) {
  const Program& program = cycle.program;
  const std::size_t cycleIndex = cycle.index;
  if (!request.p || !request.q) {
    return Error{request.line, request.column,
                 fmt::format("{} needs P(ns) and Q(nf), the N numbers of the contour's first "
                             "and last blocks; {} is missing",
                             request.cycle, request.p ? "Q" : "P")};
  }
  auto first = findSequence(program, cycleIndex, request, *request.p);
  if (!first.ok()) return first.error();
  auto last = findSequence(program, cycleIndex, request, *request.q);
  if (!last.ok()) return last.error();
  ContourSpan span{first.value(), last.value(), first.value()};
  if (span.last < span.first) {
    return Error{request.line, request.q->column,
                 fmt::format("{} {} {}: N{} comes before N{}; Q names the contour's last block",
                             request.cycle, request.p->text(), request.q->text(),
                             *program.block(span.last).sequenceNumber,
                             *program.block(span.first).sequenceNumber)};
  }
  const std::string name = spanName(program, span);
  while (span.start < span.last) {
    const ProgramBlock block = program.block(span.start);
    if (!block.skipped && !isLabelOnly(program, block)) break;
    ++span.start;
  }
  int count = 0;
  std::set<int> numbers;
  for (std::size_t i = span.first; i <= span.last; ++i) {
    const ProgramBlock& block = program.block(i);
    if (block.skipped) continue;
    ++count;
    if (const auto* macroBlock = block.macroBlock(); macroBlock != nullptr && macroBlock->statement) {
      return Error{block.line, block.column,
                   fmt::format("a macro statement is not allowed in the contour of {} ({}): only blocks of "
                               "G00–G03, G04, G96/G97, G98/G99 and G40–G42",
                               request.cycle, name)};
    }
    auto words = sortedWords(cycle.program, block, cycle.variables, state, options);
    if (!words.ok()) return words.error();
    if (block.sequenceNumber && !numbers.insert(*block.sequenceNumber).second) {
      return Error{block.line, block.column,
                   fmt::format("N{} appears twice in the contour of {} ({}); give each block "
                               "its own N number",
                               *block.sequenceNumber, request.cycle, name)};
    }
    auto status = checkContourBlock(words.value(), i == span.start, request.cycle, name);
    if (!status.ok()) return status.error();
  }
  if (count > kMaxContourBlocks) {
    return Error{request.line, request.column,
                 fmt::format("the contour of {} ({}) has {} blocks; at most {} are allowed",
                             request.cycle, name, count, kMaxContourBlocks)};
  }
  return span;
}

Result<BlockRun> runContourBlocks(const BlockPlace& cycle, ContourSpan span,
                                  ModalState state, const InterpreterOptions& options) {
  BlockRun outcome;
  // The contour's blocks describe the cycle's path; whether a tool is selected when it cuts is
  // asked of the cycle's own block and its moves (block_executor.cpp), not of each contour block.
  const bool cutWithoutToolSaid = state.cutWithoutToolSaid;
  state.cutWithoutToolSaid = true;
  for (std::size_t i = span.first; i <= span.last; ++i) {
    const ProgramBlock& block = cycle.program.block(i);
    if (block.skipped) continue;
    auto words = sortedWords(cycle.program, block, cycle.variables, state, options);
    if (!words.ok()) return words.error();
    auto done = cycle.runner.run(words.value(), std::move(state), options, block.ordinal);
    if (!done.ok()) return done.error();
    state = std::move(done.value().state);
    const auto& moves = done.value().moves;
    outcome.moves.insert(outcome.moves.end(), moves.begin(), moves.end());
    const auto& warnings = done.value().warnings;
    outcome.warnings.insert(outcome.warnings.end(), warnings.begin(), warnings.end());
  }
  state.cutWithoutToolSaid = cutWithoutToolSaid;
  outcome.state = std::move(state);
  return outcome;
}

Result<ExtractedContour> extractContour(const BlockPlace& cycle, ContourSpan span,
                                        const ModalState& state,
                                        const InterpreterOptions& options) {
  auto run = runContourBlocks(cycle, span, state, options);
  if (!run.ok()) return run.error();
  std::vector<Error> cornerWarnings;  // G70 gives them, when it runs the same blocks
  if (auto corners = insertCorners(run.value().moves, cornerWarnings); !corners.ok()) return corners.error();
  const ProgramBlock& first = cycle.program.block(span.start);
  auto firstWords = sortedWords(cycle.program, first, cycle.variables, state, options);
  if (!firstWords.ok()) return firstWords.error();
  const ParsedBlock& firstParsed = firstWords.value();
  ExtractedContour extracted;
  extracted.firstBlockRapid = firstParsed.gCode(GGroup::Motion)->number == 0;
  extracted.firstBlockHasX = firstParsed.has('X') || firstParsed.has('U');
  extracted.firstBlockHasZ = firstParsed.has('Z') || firstParsed.has('W');
  for (const Move& move : run.value().moves) {
    if (move.kind == MoveKind::Dwell) continue;
    if (move.block == first.ordinal) ++extracted.firstBlockSegments;
    extracted.contour.push_back({move.kind, move.from, move.to, move.center, move.line,
                                 move.column});
    extracted.noseComps.push_back(move.noseComp);
  }
  return extracted;
}

}  // namespace lathesim::interp
