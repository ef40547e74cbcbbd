#include "interp/cycles/thread_words.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "interp/text/word_units.hpp"

namespace lathesim::interp {

constexpr double kMaxStartAngleThousandths = 360000.0;
constexpr double kThousandthsPerDegree = 1000.0;

Result<double> takeLeadMm(ParsedBlock& block, ModalState& state, const ThreadingWords& words, std::string_view name,
                          int anchor, bool fHere) {
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
    }
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
  if (const auto along = block.take(alongLetter)) {
    if (words.hncRunoutRE && along->value < 0) {
      return Error{block.line, along->column,
                   fmt::format("{} {} is not a run-out length: expected a number ≥ 0", name, along->text())};
    }
    kept.alongMm = std::abs(lengthMm(*along, reading));
  }
  return kept;
}

ThreadRunout cycleRunout(const RunoutWords& words, double defaultMm) {
  if (!words.acrossMm && !words.alongMm) return {defaultMm, defaultMm};
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
