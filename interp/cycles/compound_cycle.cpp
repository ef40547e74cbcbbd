#include "interp/cycles/compound_cycle_block.hpp"

#include "interp/state/block_work.hpp"



namespace lathesim::interp {
namespace compound_detail {


Result<CompoundOutcome> CompoundCycle::run() {
  if (auto problem = planeProblem(state_.plane, code_.text, "a cycle")) return errorAt(code_.column, *problem);
  Status status = success();
  switch (code_.number) {
    case 70: status = finishing(); break;
    case 71:
    case 72: status = roughing(); break;
    case 73: status = patternRepeat(); break;
    case 74: status = peck(kFacePeckCycle); break;
    case 75: status = peck(kGroovePeckCycle); break;
    default: status = multipleThreading(); break;
  }
  if (!status.ok()) return status.error();
  return std::move(outcome_);
}

Status CompoundCycle::positive(const std::optional<Word>& word, std::string_view meaning) const {
  if (word && word->value <= 0) {
    return errorAt(word->column, fmt::format("{} {} is not {}: expected a number > 0",
                                             code_.text, word->text(), meaning));
  }
  return success();
}

Status CompoundCycle::notNegative(const std::optional<Word>& word,
                                  std::string_view meaning) const {
  if (word && word->value < 0) {
    return errorAt(word->column, fmt::format("{} {} is not {}: expected a number ≥ 0",
                                             code_.text, word->text(), meaning));
  }
  return success();
}

Status CompoundCycle::oneOf(const std::optional<Word>& absolute,
                            const std::optional<Word>& incremental, std::string_view axis) const {
  if (!absolute || !incremental) return success();
  return errorAt(std::max(absolute->column, incremental->column),
                 fmt::format("{} and {} both give the {} axis; give one of them",
                             absolute->text(), incremental->text(), axis));
}

Status CompoundCycle::needFeed() const {
  if (auto problem = zeroFeedProblem(state_.feed, code_.text)) return errorAt(code_.column, *problem);
  if (state_.feed) return success();
  return errorAt(code_.column, fmt::format("feed rate F is not set: {} cuts at feed; give F "
                                           "(e.g. F0.2 mm/rev) in this block or before it",
                                           code_.text));
}

Result<ContourSpan> CompoundCycle::contourSpan() const {
  const ContourRequest request{code_.text, block_.take('P'), block_.take('Q'), block_.line,
                               code_.column};
  if (place_ == nullptr) {
    return errorAt(code_.column, fmt::format("{} needs its contour blocks, but this block is "
                                             "run on its own",
                                             code_.text));
  }
  return findContourBlocks(*place_, request, state_, options_);
}

// GSK (lathe-cycles.md §8): a G41/G42 in force before G71–G73 is suspended for the roughing
// and restored after it; only G41/G42 in the contour (its ns block) compensate it. G70 is
// different: it finishes in the compensation in force (finishing()).
ModalState CompoundCycle::contourStartState() const {
  ModalState start = state_;
  start.noseSide = NoseSide::None;
  return start;
}

// The contour G71–G73 rough against: the ns–nf path, offset by the nose radius when the
// contour's blocks ask for G41/G42 (the cycle ends the compensation).
Result<ExtractedContour> CompoundCycle::contour(ContourSpan span) const {
  auto extracted = extractContour(*place_, span, contourStartState(), options_);
  if (!extracted.ok()) return extracted.error();
  auto compensated = compensatedContour(extracted.value().contour, extracted.value().noseComps);
  if (!compensated.ok()) return compensated.error();
  extracted.value().contour = std::move(compensated.value());
  if (extracted.value().contour.empty()) {
    return errorAt(code_.column, fmt::format("the contour of {} makes no move from the cycle "
                                             "start point",
                                             code_.text));
  }
  return extracted;
}

// G71–G73 go on after the nf block, skipping the contour that follows them (not when the
// contour was written before the cycle: that would run the cycle again).
void CompoundCycle::continueAfter(ContourSpan span) {
  if (span.last > place_->index) outcome_.continueAfter = span.last;
}

// G71–G73 rough the contour of `b`: said in the outcome, with whether its blocks compensate it.
void CompoundCycle::roughs(const ContourBlock& b) {
  outcome_.contour = b.span;
  const auto& comps = b.contour.noseComps;
  outcome_.contourCompensated =
      std::any_of(comps.begin(), comps.end(), [](const NoseComp& comp) { return comp.side != NoseSide::None; });
}

// G70 P Q: the contour blocks as written, with their own F, S and T, then rapid back to A.
// A G41/G42 in force (`G00 G42 X42. Z2.` then `G70 P Q`, the manuals' form on Fanuc and GSK)
// carries on into the contour: its moves continue the chain the G42 block started
// (nose_compensation.hpp) and the rapid back to A, a cycle leg, cancels it. A G41/G42 in the
// ns block compensates as in any chain.
Status CompoundCycle::finishing() {
  auto span = contourSpan();
  if (!span.ok()) return span.error();
  if (span.value().first > place_->index) {
    const ProgramBlock ns = place_->program.block(span.value().first);
    return errorAt(code_.column, fmt::format("{}'s contour N{} starts on line {}, after it: G70 finishes a contour "
                                             "roughed before it and must follow its blocks (GSK980TDi §3.23.4 "
                                             "note 1)",
                                             code_.text, *ns.sequenceNumber, ns.line));
  }
  const RZ start = state_.position;
  auto run = runContourBlocks(*place_, span.value(), state_, options_);
  if (!run.ok()) return run.error();
  const NoseSide before = state_.noseSide;  // a G40/G41/G42 in the contour ends with the cycle
  state_ = std::move(run.value().state);
  state_.noseSide = before;
  outcome_.contourMoves = std::move(run.value().moves);
  outcome_.contour = span.value();
  outcome_.warnings = std::move(run.value().warnings);
  outcome_.legs.push_back({MoveKind::Rapid, state_.position, start, 0, RZ(0, 0)});
  if (state_.position == start) outcome_.legs.clear();
  state_.position = start;
  return success();
}

// G71 U(Δd) R(e) / G72 W(Δd) R(e); then G71/G72 P Q U(Δu) W(Δw).
Status CompoundCycle::roughing() {
  if (options_.dialect == Dialect::Haas) return haasRoughing();
  const bool turning = code_.number == 71;
  if (!block_.has('P') && !block_.has('Q')) {
    const auto depth = block_.take(turning ? 'U' : 'W');
    const auto retract = block_.take('R');
    if (auto s = positive(depth, "a depth of cut Δd"); !s.ok()) return s;
    if (auto s = notNegative(retract, "a retract distance e"); !s.ok()) return s;
    if (depth) state_.compound.roughingDepthMm = length(*depth);
    if (retract) state_.compound.roughingRetractMm = length(*retract);
    state_.compound.roughingGiven = true;
    return success();
  }
  // GSK's K and J (§3.23.1): K1 asks for the full monotonic check, which lathesim always makes
  // (how the GSK roughs a contour it did not check is not documented); J1 asks type II for one
  // more pass along the rough contour, by a path the manual does not give.
  block_.take('K');
  if (const auto j = block_.take('J'); j && j->value == 1) {
    return errorAt(j->column, fmt::format("{} {}: the GSK's extra pass along the rough contour is not simulated (the "
                                          "manual does not say how the tool gets back to its start); leave J out",
                                          code_.text, j->text()));
  }
  auto read = contourBlock();
  if (!read.ok()) return read.error();
  if (!state_.compound.roughingGiven) {
    state_.compound.roughingGiven = true;
    outcome_.warnings.push_back(
        {block_.line, code_.column,
         fmt::format("{0} P… Q… runs without a first block {0} {1}(Δd) R(e): Δd {2:g} mm and e {3:g} mm come from the "
                     "control's parameters (g71_depth, g71_retract), not from the program",
                     code_.text, turning ? 'U' : 'W', state_.compound.roughingDepthMm,
                     state_.compound.roughingRetractMm)});
  }
  const ContourBlock& b = read.value();
  const ExtractedContour& c = b.contour;
  RoughingParams params;
  params.depthMm = state_.compound.roughingDepthMm;
  params.retractMm = state_.compound.roughingRetractMm;
  params.allowanceXMm = b.allowanceXMm;
  params.allowanceZMm = b.allowanceZMm;
  params.typeII = c.firstBlockHasX && c.firstBlockHasZ;
  params.retractAtFeed = options_.control.roughingRetractAtFeed;
  params.maxLegs = options_.maxMoves;
  const RZ start = state_.position;
  auto legs = turning ? turningRoughingLegs(start, c.contour, params)
                      : facingRoughingLegs(start, c.contour, params);
  if (!legs.ok()) return legs.error();
  outcome_.legs = std::move(legs.value());
  roughs(b);
  continueAfter(b.span);
  return success();
}

// Haas: one block, G71/G72 P Q [U W D I K F] (Haas lathe manual, "G71 O.D./I.D. Stock Removal
// Cycle"): D the depth of each pass (a radius; Setting 72, control g71_depth, when left out),
// the retract Setting 73 (g71_retract); U/W the finishing allowance left for G70 (as Fanuc's
// second block), I/K the rough allowance (X as a radius, Z) that the roughing levels leave on
// top of it. The levels rough against the contour shifted by (U/2 + I, W + K); the pass along
// the contour that ends the cycle follows it shifted by (U/2, W) (stock_removal.cpp).
Status CompoundCycle::haasRoughing() {
  const bool turning = code_.number == 71;
  if (!block_.has('P') || !block_.has('Q')) {
    return errorAt(code_.column, fmt::format("{0} in the Haas form is one block, {0} P(first N) Q(last N) [U W D I K "
                                             "F]: P and Q name the contour (the two-block form {0} {1} R; {0} P Q "
                                             "is Fanuc's: --dialect fanuc-a)",
                                             code_.text, turning ? 'U' : 'W'));
  }
  if (const auto r = block_.take('R')) {
    return errorAt(r->column, fmt::format("{} {}: YASNAC's type II selection is not read; a contour whose first "
                                          "block moves both X and Z is type II already",
                                          code_.text, r->text()));
  }
  const auto depth = block_.take('D');
  const auto roughX = block_.take('I');
  const auto roughZ = block_.take('K');
  if (auto s = positive(depth, "a depth of cut D"); !s.ok()) return s;
  auto read = contourBlock();
  if (!read.ok()) return read.error();
  const ContourBlock& b = read.value();
  RoughingParams params;
  params.depthMm = depth ? length(*depth) : options_.control.roughingDepthMm;
  params.retractMm = options_.control.roughingRetractMm;
  params.allowanceXMm = b.allowanceXMm;
  params.allowanceZMm = b.allowanceZMm;
  params.roughAllowanceXMm = roughX ? length(*roughX) : 0.0;
  params.roughAllowanceZMm = roughZ ? length(*roughZ) : 0.0;
  params.typeII = b.contour.firstBlockHasX && b.contour.firstBlockHasZ;
  params.retractAtFeed = options_.control.roughingRetractAtFeed;
  params.maxLegs = options_.maxMoves;
  params.haasTroughs = true;
  if (auto problem = haasContourProblem(state_.position, b.contour.contour, turning)) return *problem;
  auto legs = turning ? turningRoughingLegs(state_.position, b.contour.contour, params)
                      : facingRoughingLegs(state_.position, b.contour.contour, params);
  if (!legs.ok()) return legs.error();
  outcome_.legs = std::move(legs.value());
  roughs(b);
  continueAfter(b.span);
  return success();
}

Result<CompoundCycle::ContourBlock> CompoundCycle::contourBlock() {
  auto span = contourSpan();
  if (!span.ok()) return span.error();
  const auto u = block_.take('U');
  const auto w = block_.take('W');
  if (auto s = needFeed(); !s.ok()) return s.error();
  auto extracted = contour(span.value());
  if (!extracted.ok()) return extracted.error();
  return ContourBlock{span.value(), std::move(extracted).value(), u ? length(*u) / 2.0 : 0.0,
                      w ? length(*w) : 0.0};
}

// G73's relief Δi (X, a radius), Δk and passes d, kept for the blocks after.
Status CompoundCycle::patternValues(const std::optional<Word>& reliefX, const std::optional<Word>& reliefZ,
                                    const std::optional<Word>& passes) {
  if (passes && passes->value >= 1 && std::floor(passes->value) != passes->value)  // R2. is read as 2, R2.5 is no count
    return errorAt(passes->column,
                   fmt::format("G73 {} is not a number of passes d: {}", passes->text(), decimalPointSlip(*passes)));
  if (passes && (passes->value < 1 || std::floor(passes->value) != passes->value)) {
    return errorAt(passes->column, fmt::format("G73 {} is not a number of passes d: expected a "
                                               "whole number ≥ 1",
                                               passes->text()));
  }
  // Each pass makes a move at least: more passes than the move limit are refused as it is
  // (and before a count past int's range is stored).
  if (passes && passes->value > std::min<double>(static_cast<double>(options_.maxMoves), INT_MAX))
    return *moveLimitError(options_.maxMoves + 1, options_.maxMoves, block_.line, passes->column);
  if (reliefX) state_.compound.patternReliefXMm = length(*reliefX);
  if (reliefZ) state_.compound.patternReliefZMm = length(*reliefZ);
  if (passes) state_.compound.patternPasses = static_cast<int>(passes->value);
  state_.compound.patternGiven = true;
  return success();
}

// G73 U(Δi) W(Δk) R(d); then G73 P Q U(Δu) W(Δw). Haas writes one block, G73 P Q I(Δi) K(Δk)
// D(d) U W F.
Status CompoundCycle::patternRepeat() {
  if (options_.dialect == Dialect::Haas) {
    if (auto s = patternValues(block_.take('I'), block_.take('K'), block_.take('D')); !s.ok()) return s;
  } else if (!block_.has('P') && !block_.has('Q')) {
    return patternValues(block_.take('U'), block_.take('W'), block_.take('R'));
  }
  auto read = contourBlock();
  if (!read.ok()) return read.error();
  if (!state_.compound.patternGiven) {
    state_.compound.patternGiven = true;
    outcome_.warnings.push_back(
        {block_.line, code_.column,
         fmt::format("G73 P… Q… runs without a first block G73 U(Δi) W(Δk) R(d): Δi {:g} mm, Δk {:g} mm and d {} come "
                     "from the control's parameters (g73_relief_x, g73_relief_z, g73_passes), not from the program",
                     state_.compound.patternReliefXMm, state_.compound.patternReliefZMm,
                     state_.compound.patternPasses)});
  }
  const ContourBlock& b = read.value();
  const ExtractedContour& c = b.contour;
  PatternRepeatParams params;
  params.reliefXMm = state_.compound.patternReliefXMm;
  params.reliefZMm = state_.compound.patternReliefZMm;
  params.passes = state_.compound.patternPasses;
  params.singlePassRunsTwice = options_.control.patternSinglePass == PatternSinglePass::RunsTwice;
  params.allowanceXMm = b.allowanceXMm;
  params.allowanceZMm = b.allowanceZMm;
  auto legs = patternRepeatLegs(state_.position, c.contour, c.firstBlockSegments, c.firstBlockRapid, params,
                                options_.maxMoves);
  if (!legs) return *moveLimitError(options_.maxMoves + 1, options_.maxMoves, block_.line, code_.column);
  outcome_.legs = std::move(*legs);
  roughs(b);
  continueAfter(b.span);
  return success();
}

// G74/G75 R(e); then G74/G75 X(U) Z(W) P Q R(Δd) F.
Status CompoundCycle::peck(const PeckCycle& cycle) {
  const bool g74 = cycle.pecksAlongZ;
  const bool second = g74 ? block_.has('Z') || block_.has('W') : block_.has('X') || block_.has('U');
  if (!second) {
    const auto r = block_.take('R');
    if (auto s = notNegative(r, "a retract distance e"); !s.ok()) return s;
    if (r) state_.compound.peckRetractMm = length(*r);
    return success();
  }
  // Haas writes the pecks as lengths, I along X (a radius) and K along Z, and D for the relief
  // at the bottom; the back-off after each peck is the control's (Setting 22: g74_retract).
  const bool haas = options_.dialect == Dialect::Haas;
  const auto x = block_.take('X');
  const auto u = block_.take('U');
  const auto z = block_.take('Z');
  const auto w = block_.take('W');
  const auto p = block_.take(haas ? 'I' : 'P');
  const auto q = block_.take(haas ? 'K' : 'Q');
  const auto r = block_.take(haas ? 'D' : 'R');
  if (auto s = oneOf(x, u, "X"); !s.ok()) return s;
  if (auto s = oneOf(z, w, "Z"); !s.ok()) return s;
  for (const auto* word : {&p, &q}) {
    if (auto s = notNegative(*word, "a distance"); !s.ok()) return s;
  }
  if (auto s = needFeed(); !s.ok()) return s;
  const RZ start = state_.position;
  RZ end = start;
  if (x) end.x() = length(*x) / 2.0;
  if (u) end.x() += length(*u) / 2.0;
  if (z) end.y() = length(*z);
  if (w) end.y() += length(*w);

  // GSK documents G74/G75's X-axis P and G74's R(Δd) as diameters, Fanuc figures as radii
  // (control parameter g74_x_words). G75's back-off e is a radius like every other retract.
  const double xScale = options_.control.peckXWordsAreDiameters && !haas ? 0.5 : 1.0;
  const auto increment = [this, haas](const std::optional<Word>& word, double scale) {
    if (!word) return 0.0;
    return (haas ? length(*word) : incrementLengthMm(*word, NumberReading::of(options_.control, state_.inch))) * scale;
  };
  // G74: Q pecks in Z, P steps in X; G75: P pecks in X, Q steps in Z.
  const std::optional<Word>& peckWord = g74 ? q : p;
  const std::optional<Word>& shiftWord = g74 ? p : q;
  PeckParams params;
  params.peckMm = increment(peckWord, g74 ? 1.0 : xScale);
  params.shiftMm = increment(shiftWord, g74 ? xScale : 1.0);
  params.retractMm = state_.compound.peckRetractMm;
  // R(Δd) may be negative: its size is the relief; its sign the direction when the block moves
  // only the peck axis, on a control that reads it so (g74_relief_without_shift).
  const double relief = increment(r, g74 ? xScale : 1.0);
  params.reliefMm = std::abs(relief);
  params.reliefDirectionWithoutShift =
      options_.control.peckReliefWithoutShift == PeckReliefWithoutShift::BySign && relief < 0 ? -1.0 : 1.0;

  const double peckTravel = g74 ? end.y() - start.y() : end.x() - start.x();
  const double shiftTravel = g74 ? end.x() - start.x() : end.y() - start.y();
  const char peckLetter = haas ? (g74 ? 'K' : 'I') : g74 ? 'Q' : 'P';
  const char shiftLetter = haas ? (g74 ? 'I' : 'K') : g74 ? 'P' : 'Q';
  if (peckTravel != 0 && params.peckMm <= 0) {
    return errorAt(peckWord ? peckWord->column : code_.column,
                   fmt::format("{} needs {}(Δ{}) > 0, the depth of each peck along {}", code_.text,
                               peckLetter, g74 ? 'k' : 'i', g74 ? "Z" : "X"));
  }
  if (shiftTravel != 0 && params.shiftMm <= 0) {
    return errorAt(shiftWord ? shiftWord->column : code_.column,
                   fmt::format("{} needs {}(Δ{}) > 0, the {} shift between plunges, because the "
                               "end point's {} differs from the start",
                               code_.text, shiftLetter, g74 ? 'i' : 'k', g74 ? "X" : "Z",
                               g74 ? "X" : "Z"));
  }
  auto legs = peckCycleLegs(cycle, start, end, params, options_.maxMoves);
  if (!legs) return *moveLimitError(options_.maxMoves + 1, options_.maxMoves, block_.line, code_.column);
  outcome_.legs = std::move(*legs);
  return success();
}

}  // namespace compound_detail

bool isCompoundCycle(const Code& code) { return code.number >= 70 && code.number <= 76; }

Result<CompoundOutcome> runCompoundCycle(const Code& code, ParsedBlock& block, ModalState& state,
                                         const InterpreterOptions& options,
                                         const BlockPlace* place, bool feedGiven) {
  return compound_detail::CompoundCycle(code, block, state, options, place, feedGiven).run();
}

}  // namespace lathesim::interp
