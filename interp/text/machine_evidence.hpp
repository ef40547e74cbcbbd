#pragma once
// What a program's own text says of the machine it was written for, read in one pass before it
// runs (lathe-gcode.md, "Reading the dialect from the program"): the marks that only one
// G-code system, one control family or one convention explains, each where it stands. What
// is concluded from them is machine_choice.hpp's; this only collects.
//
//   SystemA      G98/G99, G50, G32; U/W beside a move (system B/C have no U/W axes)
//   SystemB      G94/G95 as a feed mode (no X/Z in the block; G94 with F), G92 S (the rpm
//                clamp), G77/G78/G79, G90/G91 as distance modes (G91 anywhere, G90 with no
//                X/Z), G33
//   Hnc          G80/G81/G82 used as cycles with X(U) and Z(W) — not with the R or Q that
//                Fanuc's drilling cycles of the same numbers take
//   Haas         one-block G71/G72 with D, M97, G187
//   FanucCorner  ,C / ,R corner words (read by controls whose corner words are ,C/,R)
//   Inch         G20
//   Trainer      a school trainer's program (Denford, Boxford, Emco): a `[BILLET` stock line,
//                M06 beside a T word (the trainers' tool change; Fanuc, GSK and Haas lathes
//                index the turret by the T word alone)
// Text inside ( ) comments is never evidence; a line opening with '[' (a trainer's directive,
// which the interpreter skips) is evidence only as a `[BILLET` line.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "interp/text/control_family.hpp"
#include "interp/text/stated_stock.hpp"
#include "interp/base/paged_text.hpp"

namespace lathesim::interp {

enum class EvidenceKind { SystemA, SystemB, Hnc, Haas, FanucCorner, Inch, Trainer };
inline constexpr std::size_t kEvidenceKinds = 7;

/// One mark, as written ("G95", "G92 S2500"), where it stands.
struct EvidenceMark {
  EvidenceKind kind = EvidenceKind::SystemA;
  int line = 0;
  int column = 0;
  std::string text;
};

/// A length word as written: X, Z, U or W.
struct LengthWord {
  int line = 0;
  int column = 0;
  std::string text;  // "Z-23"
  double value = 0;  // as written (23 for Z23, whatever the control makes of it)
};

struct MachineEvidence {
  /// Per kind, the first kMarksKept marks (enough to name), and how many there were.
  static constexpr std::size_t kMarksKept = 3;
  std::array<std::vector<EvidenceMark>, kEvidenceKinds> marks;
  std::array<std::size_t, kEvidenceKinds> counts{};
  /// Codes both systems read, with other meanings (G90/G92/G94 with X or Z: a cycle in system
  /// A, a move in B), the first kMarksKept: what thin evidence could not tell apart.
  std::vector<EvidenceMark> ambiguous;
  std::optional<ForeignProgram> foreign;  // the first line of another control family

  // Lengths (X Z U W words): how many are written with a point and how many without (nonzero
  // bare integers, which a least-increment control reads in 0.001 mm), the first bare one, and
  // the largest of each as written.
  std::size_t pointLengths = 0;
  std::size_t bareLengths = 0;
  std::optional<LengthWord> firstBareLength;
  std::optional<LengthWord> largestPointLengthWord;
  double largestPointLength = 0;
  double largestBareLength = 0;
  bool metricStated = false;  // G21 seen

  // Not of the machine but found in the same walk of the lines, so that the text is read once:
  // the bar the program states for itself (stated_stock.hpp), the first statement.
  std::optional<StatedStock> stock;

  const std::vector<EvidenceMark>& of(EvidenceKind kind) const { return marks[static_cast<std::size_t>(kind)]; }
  std::size_t count(EvidenceKind kind) const { return counts[static_cast<std::size_t>(kind)]; }
};

/// The evidence of `text` (and the bar it states), read once, line by line.
MachineEvidence readMachineEvidence(PagedText text);

/// The length words without a decimal point in `line` (a line of program text), in order.
std::vector<LengthWord> bareLengthsIn(std::string_view line, int lineNumber);

}  // namespace lathesim::interp
