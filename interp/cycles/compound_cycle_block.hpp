#pragma once
// The compound cycles' block, as the two files that run it share it: compound_cycle.cpp (the
// contour cycles G70–G73 and G74/G75) and compound_threading.cpp (G76 in its Fanuc, GSK and
// HNC forms). Only those two include it.

#include <optional>
#include <string>
#include <string_view>

#include "interp/cycles/compound_cycle.hpp"
#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <fmt/format.h>
#include "interp/cycles/contour_blocks.hpp"
#include "interp/cycles/g73_cycle.hpp"
#include "interp/cycles/g76_cycle.hpp"
#include "interp/cycles/haas_contour.hpp"
#include "interp/cycles/haas_g76.hpp"
#include "interp/cycles/thread_words.hpp"
#include "interp/compensation/nose_compensation.hpp"
#include "interp/state/move_limit.hpp"
#include "interp/cycles/peck_cycle.hpp"
#include "interp/text/label_number.hpp"
#include "interp/cycles/roughing_cycle.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp::compound_detail {

class CompoundCycle {
 public:
  CompoundCycle(const Code& code, ParsedBlock& block, ModalState& state,
                const InterpreterOptions& options, const BlockPlace* place, bool feedGiven)
      : code_(code), block_(block), state_(state), options_(options), place_(place), feedGiven_(feedGiven) {}

  Result<CompoundOutcome> run();

 private:
  Error errorAt(int column, std::string message) const {
    return Error{block_.line, column, std::move(message)};
  }
  // A length word in mm, noted for the mixed decimal point warning.
  double length(const Word& word) {
    state_.lengthWriting.note(word, block_.line, place_ ? place_->program.block(place_->index).ordinal : -1);
    return lengthMm(word, NumberReading::of(options_.control, state_.inch));
  }
  Status positive(const std::optional<Word>& word, std::string_view meaning) const;
  Status notNegative(const std::optional<Word>& word, std::string_view meaning) const;
  Status oneOf(const std::optional<Word>& absolute, const std::optional<Word>& incremental,
               std::string_view axis) const;
  Status needFeed() const;
  Result<ContourSpan> contourSpan() const;
  Result<ExtractedContour> contour(ContourSpan span) const;
  // The second block of G71–G73: P Q U(Δu) W(Δw) F, its contour run from the start point.
  struct ContourBlock {
    ContourSpan span;
    ExtractedContour contour;
    double allowanceXMm;  // Δu/2, a radius
    double allowanceZMm;  // Δw
  };
  Result<ContourBlock> contourBlock();
  ModalState contourStartState() const;
  void continueAfter(ContourSpan span);
  void roughs(const ContourBlock& b);

  Status finishing();  // G70
  Status roughing();   // G71, G72
  Status haasRoughing();  // G71, G72 in the Haas one-block form
  Status patternRepeat();  // G73
  Status patternValues(const std::optional<Word>& reliefX, const std::optional<Word>& reliefZ,
                       const std::optional<Word>& passes);
  Status peck(const PeckCycle& cycle);  // G74, G75
  Status multipleThreading();  // G76
  Status threadingParameters();  // G76's first block
  Status hncMultipleThreading();  // HNC's one-block G76
  // The words of a G76 that the checks point at.
  struct ThreadPassWords {
    const std::optional<Word>& height;      // k
    const std::optional<Word>& firstDepth;  // Δd
    const std::optional<Word>& endZ;        // Z or W
  };
  Status checkThreadPassWords(const ThreadPassWords& words, const RZ& start, const RZ& end, char heightLetter,
                              char depthLetter) const;
  Status threadPasses(const RZ& start, const RZ& end, const MultipleThreadingParams& params,
                      const ThreadPassWords& words);

  const Code& code_;
  ParsedBlock& block_;
  ModalState& state_;
  const InterpreterOptions& options_;
  const BlockPlace* place_;
  bool feedGiven_;
  CompoundOutcome outcome_;
  std::vector<Error>& warnings_ = outcome_.warnings;
};

}  // namespace lathesim::interp::compound_detail
