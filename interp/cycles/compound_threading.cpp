#include "interp/cycles/compound_cycle_block.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

// G76, the multiple threading cycle: its parameter block, its Fanuc/GSK two-block form and
// HNC's one-block form, each making its passes (g76_cycle.hpp).
namespace lathesim::interp::compound_detail {

// G76 P(m)(r)(a) Q(Δdmin) R(d) [J K]: modal values for the second blocks that follow.
Status CompoundCycle::threadingParameters() {
  const ThreadingWords words = threadingWords(options_.dialect);
  const auto p = block_.take('P');
  const auto q = block_.take('Q');
  const auto r = block_.take('R');
  CompoundCycleParams& kept = state_.compound;
  if (p) {
    // m, r and a, two digits each: six digits give all three; GSK reads one or two digits as a
    // alone and three or four as r and a (lathe-cycles.md §6).
    const bool integral = p->number.find_first_not_of("0123456789") == std::string::npos;
    if (!integral || p->number.size() > 6) {
      return errorAt(p->column, fmt::format("G76 {} is not P(m)(r)(a): expected up to six digits, two each for "
                                            "the finishing passes m, the run-out r (in 0.1 lead) and the tool "
                                            "angle a, e.g. P020560",
                                            p->text()));
    }
    const long digits = std::stol(p->number);
    const int a = static_cast<int>(digits % 100);
    const std::vector<int> fanucAngles{80, 60, 55, 30, 29, 0};
    if (words.fanucToolAngles && std::find(fanucAngles.begin(), fanucAngles.end(), a) == fanucAngles.end()) {
      return errorAt(p->column, fmt::format("G76 {}: the tool angle a = {} is not one this control takes (80, 60, "
                                            "55, 30, 29 or 0)",
                                            p->text(), a));
    }
    const int m = static_cast<int>(digits / 10000);
    if (words.fanucToolAngles && p->number.size() >= 5 && m == 0) {  // Fanuc's m is 01–99 (lathe-cycles.md §6)
      return errorAt(p->column, fmt::format("G76 {}: the finishing passes m = 00 is not a number this control takes "
                                            "(01 to 99)",
                                            p->text()));
    }
    kept.threadToolAngleDeg = a;
    if (p->number.size() >= 3) kept.threadRunoutLeads = static_cast<double>((digits / 100) % 100) / 10.0;
    if (p->number.size() >= 5) kept.threadFinishingPasses = m;
  }
  if (q) {
    if (q->value < 0) return errorAt(q->column, fmt::format("G76 {} is not a minimum depth Δdmin: expected a number ≥ 0", q->text()));
    kept.threadMinDepthMm = incrementLengthMm(*q, NumberReading::of(options_.control, state_.inch));
  }
  if (auto s = notNegative(r, "a finishing allowance d"); !s.ok()) return s;
  if (r) kept.threadAllowanceMm = length(*r);
  auto runout = takeRunoutWords(block_, NumberReading::of(options_.control, state_.inch), words, {}, false, code_.text);
  if (!runout.ok()) return runout.error();
  kept.threadRunoutAcrossMm = runout.value().acrossMm;
  kept.threadRunoutAlongMm = runout.value().alongMm;
  return success();
}

// G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L): the passes (g76_cycle.hpp).
Status CompoundCycle::multipleThreading() {
  if (options_.dialect == Dialect::Haas) {  // one block: G76 X(U) Z(W) K D F [A I P] (haas_g76.hpp)
    auto legs = haasThreadingLegs(code_, block_, state_, options_, feedGiven_,
                                  [this](const Word& word) { return length(word); }, warnings_);
    if (!legs.ok()) return legs.error();
    outcome_.legs = std::move(legs.value());
    return success();
  }
  if (options_.dialect == Dialect::Hnc) return hncMultipleThreading();
  if (!block_.has('X') && !block_.has('U') && !block_.has('Z') && !block_.has('W')) return threadingParameters();
  const ThreadingWords words = threadingWords(options_.dialect);
  const ThreadEndWords endWords = takeThreadEndWords(block_);
  const auto& [x, u, z, w] = endWords;
  const auto i = block_.take('R');
  const auto k = block_.take('P');
  const auto firstDepth = block_.take('Q');
  if (auto s = oneOf(x, u, "X"); !s.ok()) return s;
  if (auto s = oneOf(z, w, "Z"); !s.ok()) return s;
  auto lead = takeLeadMm(block_, state_, words, options_.control, code_.text, code_.column, feedGiven_);
  if (!lead.ok()) return lead.error();
  const RZ start = state_.position;
  const RZ end = threadEndPoint(start, endWords, [this](const Word& word) { return length(word); });
  const NumberReading reading = NumberReading::of(options_.control, state_.inch);
  const CompoundCycleParams& kept = state_.compound;
  const ThreadPassWords passWords{k, firstDepth, endWords.endZ()};
  MultipleThreadingParams params;
  params.finishingPasses = kept.threadFinishingPasses;
  params.toolAngleDeg = kept.threadToolAngleDeg;
  params.minDepthStepMm = kept.threadMinDepthMm;
  params.finishAllowanceMm = kept.threadAllowanceMm;
  params.taperMm = i ? length(*i) : 0.0;
  params.leadMm = lead.value();
  if (auto s = checkThreadPassWords(passWords, start, end, 'P', 'Q'); !s.ok()) return s;
  params.heightMm = incrementLengthMm(*k, reading);
  params.firstDepthMm = incrementLengthMm(*firstDepth, reading);
  const RunoutWords runoutWords{kept.threadRunoutAcrossMm, kept.threadRunoutAlongMm};
  const double defaultLeads = kept.threadRunoutLeads.value_or(options_.control.threadRunoutLeads);
  const ThreadRunout runout =
      cycleRunout(runoutWords, defaultLeads * params.leadMm, options_.control.threadRunoutAngleDeg);
  params.runoutAlongMm = runout.alongMm;
  params.runoutAcrossMm = std::abs(runout.acrossMm);
  state_.compound.threadRunoutAcrossMm.reset();  // GSK's J and K hold for one cycle
  state_.compound.threadRunoutAlongMm.reset();
  return threadPasses(start, end, params, passWords);
}

// The checks every G76 form makes on the end point and on k and Δd before they are read.
Status CompoundCycle::checkThreadPassWords(const ThreadPassWords& words, const RZ& start, const RZ& end,
                                           char heightLetter, char depthLetter) const {
  if (end.y() == start.y()) {
    return errorAt(words.endZ ? words.endZ->column : code_.column,
                   fmt::format("{} cannot cut a face thread: its end Z must differ from the start point's Z{:g}",
                               code_.text, start.y()));
  }
  for (const auto& [word, letter, meaning] : {std::tuple{&words.height, heightLetter, "the thread height k"},
                                              std::tuple{&words.firstDepth, depthLetter, "the first depth of cut Δd"}}) {
    if (!*word) {
      const bool increments = options_.dialect != Dialect::Hnc;
      return errorAt(code_.column, fmt::format("{} needs {}({}): {}{}", code_.text, letter, meaning, meaning,
                                               increments ? " (without a decimal point in least increments, 0.001 "
                                                            "mm at IS-B)"
                                                          : ", a radius in mm"));
    }
    if (!((*word)->value > 0)) {
      return errorAt((*word)->column,
                     fmt::format("{} {} is not {}: expected a number > 0", code_.text, (*word)->text(), meaning));
    }
  }
  return success();
}

// The passes from A = `start` to D = `end` once every value is read (g76_cycle.hpp).
Status CompoundCycle::threadPasses(const RZ& start, const RZ& end, const MultipleThreadingParams& params,
                                   const ThreadPassWords& words) {
  if (params.finishAllowanceMm >= params.heightMm) {
    return errorAt(words.height->column, fmt::format("{} {}: the thread height k = {:g} mm must exceed the finishing "
                                                     "allowance d = {:g} mm{}",
                                                     code_.text, words.height->text(), params.heightMm,
                                                     params.finishAllowanceMm,
                                                     options_.dialect == Dialect::Hnc ? "" : " of the first block"));
  }
  constexpr int kMaxPasses = 1000;
  const auto depths = roughPassDepths(params.firstDepthMm, params.minDepthStepMm,
                                      params.heightMm - params.finishAllowanceMm, kMaxPasses);
  if (!depths) {
    return errorAt(words.firstDepth->column,
                   fmt::format("{} {} with Δdmin {:g} mm would take more than {} rough passes to reach k − d = {:g} "
                               "mm; give a larger Q(Δd) or Δdmin",
                               code_.text, words.firstDepth->text(), params.minDepthStepMm, kMaxPasses,
                               params.heightMm - params.finishAllowanceMm));
  }
  threadStateWarnings(state_, block_.line, code_.column, code_.text, warnings_);
  outcome_.legs = multipleThreadingLegs(start, end, params, *depths);
  return success();
}

// HNC's one-block G76 C(c) R(r) E(e) A(a) X(x) Z(z) I(i) K(k) U(d) V(Δdmin) Q(Δd) P(p) F(L)
// (the HNC-21T/18iT programming manual's G76, as copied by Chinese course notes: c the finishing
// passes 1–99, r and e the run-out along Z and X as increments, a the tool angle 80/60/55/30/29/0
// — those four modal —, x z the end point C (distances under G91), i the taper (radius at the
// start minus at the end), k the thread height, d the finishing allowance, Δdmin the smallest
// depth step, Δd the first depth, all radii in mm; p the spindle angle the passes start at; L
// the lead). Its passes are Fanuc's: one flank, Δd·√n clamped by Δdmin, d, c finishing passes.
// U/V given: this block's d/Δdmin; else the control's g76_allowance/g76_min_depth.
Status CompoundCycle::hncMultipleThreading() {
  const ThreadingWords words = threadingWords(options_.dialect);
  const auto c = block_.take('C');
  const auto a = block_.take('A');
  const auto x = block_.take('X');
  const auto z = block_.take('Z');
  const auto i = block_.take('I');
  const auto k = block_.take('K');
  const auto allowance = block_.take('U');
  const auto minDepth = block_.take('V');
  const auto firstDepth = block_.take('Q');
  const auto angle = block_.take('P');
  CompoundCycleParams& kept = state_.compound;
  if (c) {
    if (c->value < 1 || c->value > 99 || std::floor(c->value) != c->value) {
      return errorAt(c->column, fmt::format("{} {} is not a number of finishing passes: expected a whole number 1 "
                                            "to 99",
                                            code_.text, c->text()));
    }
    kept.threadFinishingPasses = static_cast<int>(c->value);
  }
  if (a) {
    const std::vector<double> angles{80, 60, 55, 30, 29, 0};
    if (std::find(angles.begin(), angles.end(), a->value) == angles.end()) {
      return errorAt(a->column, fmt::format("{} {}: the tool angle is not one this control takes (80, 60, 55, 30, "
                                            "29 or 0)",
                                            code_.text, a->text()));
    }
    kept.threadToolAngleDeg = a->value;
  }
  const NumberReading reading = NumberReading::of(options_.control, state_.inch);
  // R and E, the run-out: increments along Z and X (E a radius ⚠), signed as vectors; their
  // sizes are used, the cycle points them away from the cut.
  if (const auto r = block_.take('R')) kept.threadRunoutAlongMm = std::abs(lengthMm(*r, reading));
  if (const auto e = block_.take('E')) kept.threadRunoutAcrossMm = std::abs(lengthMm(*e, reading));
  for (const auto* word : {&allowance, &minDepth}) {
    if (auto s = notNegative(*word, word == &allowance ? "a finishing allowance d" : "a minimum depth Δdmin"); !s.ok())
      return s;
  }
  auto lead = takeLeadMm(block_, state_, words, options_.control, code_.text, code_.column, feedGiven_);
  if (!lead.ok()) return lead.error();
  if (!x && !z) {
    return errorAt(code_.column, fmt::format("{} needs X and Z: the end point C of the thread ({} in this dialect is "
                                             "one block, no parameter block)",
                                             code_.text, code_.text));
  }
  const RZ start = state_.position;
  RZ end = start;
  if (x) end.x() = (state_.incremental ? start.x() : 0.0) + length(*x) / 2.0;
  if (z) end.y() = (state_.incremental ? start.y() : 0.0) + length(*z);
  const ThreadPassWords passWords{k, firstDepth, z};
  if (auto s = checkThreadPassWords(passWords, start, end, 'K', 'Q'); !s.ok()) return s;
  MultipleThreadingParams params;
  params.finishingPasses = kept.threadFinishingPasses;
  params.toolAngleDeg = kept.threadToolAngleDeg;
  params.minDepthStepMm = minDepth ? lengthMm(*minDepth, reading) : options_.control.threadMinDepthMm;
  params.finishAllowanceMm = allowance ? lengthMm(*allowance, reading) : options_.control.threadAllowanceMm;
  params.taperMm = i ? length(*i) : 0.0;
  params.heightMm = lengthMm(*k, reading);
  params.firstDepthMm = lengthMm(*firstDepth, reading);
  params.leadMm = lead.value();
  params.startAngleDeg = angle ? std::fmod(std::abs(angle->value), 360.0) : 0.0;
  const double across = kept.threadRunoutAcrossMm.value_or(0.0);
  const double along = kept.threadRunoutAlongMm.value_or(0.0);
  if (across != 0.0 && along == 0.0) {
    return errorAt(code_.column, fmt::format("{}: a run-out E of {:g} mm along X needs its length along Z, R (the "
                                             "run-out's R and E are kept from the {} blocks before)",
                                             code_.text, across, code_.text));
  }
  params.runoutAlongMm = across == 0.0 ? 0.0 : along;
  params.runoutAcrossMm = across;
  return threadPasses(start, end, params, passWords);
}

}  // namespace lathesim::interp::compound_detail
