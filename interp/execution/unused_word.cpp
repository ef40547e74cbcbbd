#include "interp/execution/unused_word.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

std::optional<std::string> missingMachineryOf(const Word& word, const ParsedBlock& block, const ControlParameters& control) {
  if ((word.letter == 'c' || word.letter == 'r') && control.cornerWords == CornerWords::LD) {
    return fmt::format("{} is Fanuc's corner word (,C a chamfer, ,R a corner radius at the end of the move), which "
                       "this control does not read (its corner words are L and D): run with --control fanuc-0i-t, "
                       "or write {} for it",
                       word.text(), word.letter == 'c' ? 'L' : 'D');
  }
  // A line's angle in the word another control reads it in (drawing_angle_word).
  const bool angleA = word.letter == 'A' && control.drawingAngleWord != DrawingAngleWord::A;
  const bool angleCommaA = word.letter == 'a' && control.drawingAngleWord != DrawingAngleWord::CommaA;
  if (angleA || angleCommaA) {
    const std::string_view own = control.drawingAngleWord == DrawingAngleWord::Q ? "Q" :
                                 control.drawingAngleWord == DrawingAngleWord::A ? "A" : ",A";
    return fmt::format("{} is a line's angle where the control reads its angle in {} (drawing_angle_word), which "
                       "this control does not (its angle word is {}): {}",
                       word.text(), angleA ? "A" : ",A", own,
                       angleA ? "run with --control fanuc-0i-t" : "set drawing_angle_word = \",A\" in the setup's [control]");
  }
  if (word.letter == 'C') {
    return fmt::format("{}: this lathe has no C axis (the spindle cannot be positioned or "
                       "milled around); live tooling and C-axis work cannot be simulated",
                       word.text());
  }
  if (word.letter == 'B') {
    return fmt::format("{}: this lathe has no B axis (a sub-spindle's or a tilting tool "
                       "spindle's travel)",
                       word.text());
  }
  // Fanuc's multi-spindle control selects the spindle with P11, P12, P21, P22 beside S or M03.
  const bool spindleBlock = block.mCode(MGroup::Spindle) || block.has('S');
  const bool spindleSelect = word.number == "11" || word.number == "12" || word.number == "21" || word.number == "22";
  if (word.letter == 'P' && spindleSelect && spindleBlock) {
    return fmt::format("{} selects a spindle (multi-spindle control: P11 the main, P12 or P2x a "
                       "sub-spindle); this lathe has one spindle",
                       word.text());
  }
  return std::nullopt;
}

}  // namespace lathesim::interp
