#include "interp/cycles/thread_words.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "interp/text/word_units.hpp"

namespace lathesim::interp {

constexpr double kMaxStartAngleThousandths = 360000.0;
constexpr double kThousandthsPerDegree = 1000.0;

namespace {

// E as the control reads it in a thread block of a dialect whose E is not the run-out: sets
// the lead in `state`, or says why it cannot.
std::optional<Error> takeLeadE(ParsedBlock& block, ModalState& state, const ControlParameters& control,
                               const ThreadingWords& words, std::string_view name, bool leadGivenHere) {
  const auto e = block.take('E');
  if (!e) return std::nullopt;
  if (control.threadEWord == ThreadEWord::None) {
    return Error{block.line, e->column,
                 fmt::format("{} is not a word of {} on this control: give the lead as F (mm, or inch under G20, "
                             "per revolution){} (control.thread_e_word = \"lead\" or \"threads_per_inch\" "
                             "reads E)",
                             e->text(), name, words.threadsPerInchI ? " or I (threads per inch)" : "")};
  }
  const bool perInch = control.threadEWord == ThreadEWord::ThreadsPerInch;
  if (leadGivenHere) {
    return Error{block.line, e->column,
                 fmt::format("{} takes the lead once: F or E ({}), not both", name,
                             perInch ? "threads per inch" : "the lead with more digits")};
  }
  if (!(e->value > 0)) {
    return Error{block.line, e->column,
                 fmt::format("{} is not {}: expected a number > 0", e->text(),
                             perInch ? "a number of threads per inch" : "a lead")};
  }
  // Threads per inch whatever G20/G21 says; a lead in the unit in force.
  state.feed = perInch ? kMmPerInch / e->value : NumberReading::of(control, state.inch).mm(e->value);
  return std::nullopt;
}

}  // namespace

Result<double> takeLeadMm(ParsedBlock& block, ModalState& state, const ThreadingWords& words,
                          const ControlParameters& control, std::string_view name, int anchor, bool fHere) {
  bool leadGivenHere = fHere;
  if (words.threadsPerInchI) {
    if (const auto tpi = block.take('I')) {
      if (fHere) {
        return Error{block.line, tpi->column,
                     fmt::format("{} takes the lead as F (mm or inch per revolution) or as I (threads per "
                                 "inch), not both",
                                 name)};
      }
      if (!(tpi->value > 0)) {
        return Error{block.line, tpi->column,
                     fmt::format("{} is not a number of threads per inch: expected a number > 0", tpi->text())};
      }
      state.feed = kMmPerInch / tpi->value;  // threads per inch, whatever G20/G21 says
      leadGivenHere = true;
    }
  }
  if (!words.hncRunoutRE) {  // HNC's E is the run-out (takeRunoutWords)
    if (auto problem = takeLeadE(block, state, control, words, name, leadGivenHere)) return *problem;
  }
  if (!state.feed) {
    return Error{block.line, anchor,
                 fmt::format("the lead is not set: {} needs F (the lead, mm per revolution){}", name,
                             words.threadsPerInchI ? " or I (threads per inch)" : "")};
  }
  if (!(*state.feed > 0)) {  // F0 is legal on its own (a feed of 0), never as a lead
    return Error{block.line, anchor,
                 fmt::format("the lead is 0: {} needs F > 0 (the lead, mm per revolution){}", name,
                             words.threadsPerInchI ? " or I (threads per inch)" : "")};
  }
  return *state.feed;
}

Result<double> takeStartAngleDeg(ParsedBlock& block, std::string_view name, std::vector<Error>& warnings) {
  const auto q = block.take('Q');
  if (!q) return 0.0;
  if (q->value < 0 || q->value > kMaxStartAngleThousandths) {
    return Error{block.line, q->column,
                 fmt::format("{} {} is not a start angle: expected 0 to 360000 (Q is in 0.001°, so Q180000 "
                             "is 180°)",
                             name, q->text())};
  }
  if (q->number.find('.') != std::string::npos) {
    warnings.push_back({block.line, q->column,
                        fmt::format("{} is read in 0.001° as written without a decimal point: {:g}° (Q180000 is "
                                    "180°)",
                                    q->text(), q->value / kThousandthsPerDegree)});
  }
  return std::fmod(q->value / kThousandthsPerDegree, 360.0);
}

Result<RunoutWords> takeRunoutWords(ParsedBlock& block, const NumberReading& reading, const ThreadingWords& words,
                                    RunoutWords kept,
                                    bool signedAcross, std::string_view name) {
  if (!words.runoutJK && !words.hncRunoutRE) return kept;
  const char acrossLetter = words.runoutJK ? 'J' : 'E';
  const char alongLetter = words.runoutJK ? 'K' : 'R';
  if (const auto across = block.take(acrossLetter)) {
    const double mm = lengthMm(*across, reading);
    kept.acrossMm = signedAcross ? mm : std::abs(mm);
  }
  // HNC's R is a vector along Z (R-3 on a cut toward −Z): its size is the length.
  if (const auto along = block.take(alongLetter)) kept.alongMm = std::abs(lengthMm(*along, reading));
  if (words.hncRunoutRE && kept.acrossMm.value_or(0.0) != 0.0 && kept.alongMm.value_or(0.0) == 0.0) {
    return Error{block.line, block.column,
                 fmt::format("{}: a run-out E of {:g} mm along X needs its length along Z, R (R and E are kept "
                             "from the {} blocks before)",
                             name, *kept.acrossMm, name)};
  }
  return kept;
}

ThreadEndWords takeThreadEndWords(ParsedBlock& block) {
  ThreadEndWords words;
  words.x = block.take('X');
  words.u = block.take('U');
  words.z = block.take('Z');
  words.w = block.take('W');
  return words;
}

RZ threadEndPoint(const RZ& start, const ThreadEndWords& words, const std::function<double(const Word&)>& lengthMm) {
  RZ end = start;
  if (words.x) end.x() = lengthMm(*words.x) / 2.0;
  if (words.u) end.x() += lengthMm(*words.u) / 2.0;
  if (words.z) end.y() = lengthMm(*words.z);
  if (words.w) end.y() += lengthMm(*words.w);
  return end;
}

ThreadRunout cycleRunout(const RunoutWords& words, double defaultMm, int defaultAngleDeg) {
  if (!words.acrossMm && !words.alongMm) {
    // 45° exactly: tan 45° is not 1 in floating point.
    const bool square = defaultAngleDeg == 0 || defaultAngleDeg == 45;
    return {defaultMm, square ? defaultMm : defaultMm * std::tan(defaultAngleDeg * std::numbers::pi / 180.0)};
  }
  const double across = words.acrossMm.value_or(defaultMm);
  if (across == 0.0) return {};
  const double along = words.alongMm && *words.alongMm != 0.0 ? *words.alongMm : std::abs(across);
  return {along, across};
}

ThreadRunout chainRunout(const RunoutWords& words) {
  if (!words.acrossMm || *words.acrossMm == 0.0) return {};
  const double along = words.alongMm && *words.alongMm != 0.0 ? *words.alongMm : std::abs(*words.acrossMm);
  return {along, *words.acrossMm};
}

void threadStateWarnings(const ModalState& state, int line, int column, std::string_view name,
                         std::vector<Error>& warnings) {
  if (state.noseSide != NoseSide::None) {
    warnings.push_back({line, column,
                        fmt::format("{} under {}: thread moves get no nose radius compensation; they are made as "
                                    "programmed (cancel with G40 before threading)",
                                    name, state.noseSide == NoseSide::Left ? "G41" : "G42")});
  }
  if (state.spindleMode == SpindleMode::SurfaceSpeed) {
    warnings.push_back({line, column,
                        fmt::format("{} under G96: the spindle speed follows X, so the lead cannot hold from pass to "
                                    "pass; thread under G97",
                                    name)});
  }
}

}  // namespace lathesim::interp
