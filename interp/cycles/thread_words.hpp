#pragma once
// Reading what the thread codes G32, G92 and G76 share: the lead (F, GSK's I in threads
// per inch, Fanuc's E), the start angle Q, the run-out words, and the warnings a thread block earns
// from the state it runs in (G41/G42, G96). Lengths in mm, X ones as radii.

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "interp/control/machine_limits.hpp"
#include "interp/control/threading_words.hpp"
#include "interp/cycles/thread_cut.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/base/result.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {

/// The lead in force for thread code `name` at `anchor`: GSK's I (threads per inch, metric
/// or inch input alike) sets it to 25.4/I mm when the dialect has it; E sets it as the control
/// reads E (control.thread_e_word: the lead in the unit in force, or threads per inch; an error
/// on a control without it), except in hnc, whose E is the run-out; otherwise the F in force
/// (applied before, G20 converted). An error when none is set or two are given.
Result<double> takeLeadMm(ParsedBlock& block, ModalState& state, const ThreadingWords& words,
                          const ControlParameters& control, std::string_view name, int anchor, bool fHere);

/// Q, the start angle (lathe-cycles.md §2): 0.001° without a decimal point, 0–360000, not
/// modal (0 when absent). With a decimal point it is still read in 0.001° (GSK), with a
/// warning. In degrees.
Result<double> takeStartAngleDeg(ParsedBlock& block, std::string_view name, std::vector<Error>& warnings);

/// The run-out words of this block (GSK J/K or HNC E/R, when the dialect has them; lengths read
/// as `reading` says), over
/// `kept` (the values retained from the blocks before): a word given replaces the kept one.
/// GSK's J and K of G92/G76 are unsigned (negative values count by their size); G32's J is
/// signed. HNC's E is signed, a radius ⚠; R a length along Z, either sign (its size counts);
/// E without R is an error (where the run-out starts is not given).
Result<RunoutWords> takeRunoutWords(ParsedBlock& block, const NumberReading& reading, const ThreadingWords& words,
                                    RunoutWords kept, bool signedAcross, std::string_view name);

/// The end point's words of a G76 in the Fanuc/GSK or Haas form: X or U, Z or W.
struct ThreadEndWords {
  std::optional<Word> x, u, z, w;
  std::optional<Word> endZ() const { return z ? z : w; }  // the word that gives its Z, if any
};
ThreadEndWords takeThreadEndWords(ParsedBlock& block);

/// D, the thread's end, from the start point: X (a diameter) and Z replace its coordinates,
/// U (a diameter) and W are added to them; `lengthMm` reads a word as the block's unit says.
RZ threadEndPoint(const RZ& start, const ThreadEndWords& words, const std::function<double(const Word&)>& lengthMm);

/// G92's and G76's run-out from its words (GSK 3.24.9 notes 2–7, 3.24.12 notes 1–4):
/// neither J nor K: `defaultMm` along (No.19 or No.5130, or G76's r) and out at the control's
/// run-out angle to the Z axis (`defaultAngleDeg`, No.5131: 0 is 45°, as far across as along);
/// no J: K along and `defaultMm` across; no K, or K = 0: K = J; J = 0: none. Unsigned; the
/// cycle points it toward its start.
ThreadRunout cycleRunout(const RunoutWords& words, double defaultMm, int defaultAngleDeg);

/// G32's run-out (GSK 3.24.1 notes 2–5): none without J or with J = 0; no K or K = 0: K = |J|.
ThreadRunout chainRunout(const RunoutWords& words);

/// Warnings for a thread block run from `state`: G41/G42 in force (thread codes are not
/// compensated), G96 in force (the lead cannot hold while the rpm follows X).
void threadStateWarnings(const ModalState& state, int line, int column, std::string_view name,
                         std::vector<Error>& warnings);

}  // namespace lathesim::interp
