// G76 on a Haas lathe: one block, G76 X(U) Z(W) K D F [A I P] (Haas lathe manual, "G76
// Threading Cycle, Multiple Pass"):
//   X(U) Z(W)  the thread's end at its root (minor diameter for an OD thread)
//   K          thread height, crest to root, a radius (> 0)
//   D          first pass depth, a radius (> 0)
//   F          the lead
//   A          the tool nose (included) angle, 0–120°, written without a decimal point
//              (default 0: straight radial infeed)
//   I          taper, a radius: the thread's radius at its start minus at its end (as Fanuc's
//              R(i); the sign convention is not checked against a Haas figure ⚠)
//   P          infeed: P1 single edge, constant cutting amount (default); P3 single edge,
//              constant depth. P2 and P4 (double edge, alternating flanks) are refused.
// Depths: P1 D·√n, no pass adding less than Setting 99 (g76_min_depth); P3 n·D; the
// last rough pass at exactly K − Setting 86 (g76_allowance), then one pass at K
// when Setting 86 is not 0. With A each pass starts depth·tan(A/2) further along Z so only
// the leading flank cuts (single edge), as the two-block cycle does. The thread's chamfer is
// the machine's run-out (Settings 95/96: [machine] thread_runout). Each pass is then the
// two-block G76 pass (g76_cycle.cpp): rapid A → B_n, thread, rapid X back, rapid Z back.

#include "interp/cycles/haas_g76.hpp"

#include <cmath>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "interp/cycles/g76_cycle.hpp"
#include "interp/cycles/thread_words.hpp"

namespace lathesim::interp {

namespace {

constexpr double kDepthTolMm = 1e-9;

}  // namespace

std::optional<std::vector<double>> haasPassDepths(bool constantDepth, double firstDepthMm, double minimumCutMm,
                                                  double finalDepthMm, int maxPasses) {
  std::vector<double> depths;
  for (int n = 1; n <= maxPasses; ++n) {
    double depth = constantDepth ? n * firstDepthMm : firstDepthMm * std::sqrt(static_cast<double>(n));
    if (!depths.empty() && depth - depths.back() < minimumCutMm) depth = depths.back() + minimumCutMm;
    if (depth >= finalDepthMm - kDepthTolMm) {  // 3 × 0.3 reaches 0.9 though it sums to 0.8999…
      depths.push_back(finalDepthMm);
      return depths;
    }
    depths.push_back(depth);
  }
  return std::nullopt;
}

Result<std::vector<CycleLeg>> haasThreadingLegs(const Code& code, ParsedBlock& block, ModalState& state,
                                                const InterpreterOptions& options, bool feedGiven,
                                                const std::function<double(const Word&)>& lengthMm,
                                                std::vector<Error>& warnings) {
  const int line = block.line;
  const ThreadEndWords endWords = takeThreadEndWords(block);
  const auto& [x, u, z, w] = endWords;
  const auto k = block.take('K');
  const auto d = block.take('D');
  const auto a = block.take('A');
  const auto i = block.take('I');
  const auto p = block.take('P');
  if (const auto q = block.take('Q'); q && q->value != 0) {
    return Error{line, q->column, fmt::format("G76 {}: a start angle in the Haas G76 is not simulated; leave Q out "
                                              "(or cut each start with G32 Q)", q->text())};
  }
  for (const auto& [absolute, incremental, axis] :
       {std::tuple{&x, &u, "X"}, std::tuple{&z, &w, "Z"}}) {
    if (*absolute && *incremental) {
      return Error{line, (*incremental)->column, fmt::format("{} and {} both give the {} axis; give one of them",
                                                             (*absolute)->text(), (*incremental)->text(), axis)};
    }
  }
  if (!z && !w) {
    return Error{line, code.column, "G76 needs Z(W), the thread's end along Z (Haas: G76 X(U) Z(W) K D F)"};
  }
  for (const auto& [word, letter, meaning] :
       {std::tuple{&k, 'K', "the thread height (a radius)"}, std::tuple{&d, 'D', "the first pass depth (a radius)"}}) {
    if (!*word) {
      return Error{line, code.column, fmt::format("G76 needs {}, {}: Haas G76 X(U) Z(W) K D F", letter, meaning)};
    }
    if (!((*word)->value > 0)) {
      return Error{line, (*word)->column,
                   fmt::format("G76 {} is not {}: expected a number > 0", (*word)->text(), meaning)};
    }
  }
  double angleDeg = 0;
  if (a) {
    if (hasDecimalPoint(*a) || a->value < 0 || a->value > 120) {
      return Error{line, a->column, fmt::format("G76 {} is not a tool nose angle: expected a whole number of degrees "
                                                "0 to 120, written without a decimal point (A60)", a->text())};
    }
    angleDeg = a->value;
  }
  bool constantDepth = false;
  if (p) {
    if (p->value == 2 || p->value == 4) {
      return Error{line, p->column, fmt::format("G76 {}: double edge cutting (alternating flanks) is not simulated; "
                                                "use P1 or P3 (single edge)", p->text())};
    }
    if (p->value != 1 && p->value != 3) {
      return Error{line, p->column, fmt::format("G76 {} is not an infeed method: expected P1 (single edge, constant "
                                                "cutting amount) or P3 (single edge, constant depth)", p->text())};
    }
    constantDepth = p->value == 3;
  }
  auto lead = takeLeadMm(block, state, threadingWords(options.dialect), options.control, code.text, code.column, feedGiven);
  if (!lead.ok()) return lead.error();

  const RZ start = state.position;
  const RZ end = threadEndPoint(start, endWords, lengthMm);
  if (end.y() == start.y()) {
    return Error{line, endWords.endZ()->column,
                 fmt::format("G76 cannot cut a face thread: its end Z must differ from the start point's Z{:g}",
                             start.y())};
  }
  MultipleThreadingParams params;
  params.toolAngleDeg = angleDeg;
  params.heightMm = lengthMm(*k);
  params.firstDepthMm = lengthMm(*d);
  params.taperMm = i ? lengthMm(*i) : 0.0;
  params.leadMm = lead.value();
  params.finishAllowanceMm = options.control.threadAllowanceMm;
  params.finishingPasses = params.finishAllowanceMm > 0 ? 1 : 0;
  if (params.finishAllowanceMm >= params.heightMm) {
    return Error{line, k->column, fmt::format("G76 {}: the thread height must exceed the finish allowance {:g} mm "
                                              "(Setting 86, control g76_allowance)",
                                              k->text(), params.finishAllowanceMm)};
  }
  const ThreadRunout runout =
      cycleRunout({}, options.control.threadRunoutLeads * params.leadMm, options.control.threadRunoutAngleDeg);
  params.runoutAlongMm = runout.alongMm;
  params.runoutAcrossMm = std::abs(runout.acrossMm);

  constexpr int kMaxPasses = 1000;
  const double finalDepth = params.heightMm - params.finishAllowanceMm;
  const auto depths =
      haasPassDepths(constantDepth, params.firstDepthMm, options.control.threadMinDepthMm, finalDepth, kMaxPasses);
  if (!depths) {
    return Error{line, d->column, fmt::format("G76 {} would take more than {} passes to reach {:g} mm; give a larger D "
                                              "(or a larger g76_min_depth, Haas Setting 99)",
                                              d->text(), kMaxPasses, finalDepth)};
  }
  threadStateWarnings(state, line, code.column, code.text, warnings);
  return multipleThreadingLegs(start, end, params, *depths);
}

}  // namespace lathesim::interp
