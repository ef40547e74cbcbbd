#include "interp/text/machine_choice.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

// Dialect and control as one choice: what stating one implies of the other. A row with no
// partner reads (or is written by) more than one: the other is read from the program.
struct Pairing {
  Dialect dialect;
  std::string_view control;
};
constexpr std::array kPairings{
    Pairing{Dialect::Haas, "haas"},  // the haas preset reads Haas's one-block cycles, M97 and
                                     // Haas's M codes; Haas's cycles are read in no other preset
};

// The dialects each kind of evidence admits (lathe-gcode.md's table: system A's codes are
// Fanuc's and GSK's system A and Haas's; system B's, G94/G95 feeds and G90/G91 distance
// modes, are also HNC's).
struct Admitting {
  EvidenceKind kind;
  std::string_view name;
  std::vector<Dialect> dialects;
};

const std::vector<Admitting>& admittingTable() {
  static const std::vector<Admitting> table{
      {EvidenceKind::SystemA, "system A", {Dialect::FanucA, Dialect::Haas}},
      {EvidenceKind::SystemB, "system B", {Dialect::FanucB, Dialect::Hnc}},
      {EvidenceKind::Hnc, "HNC", {Dialect::Hnc}},
      {EvidenceKind::Haas, "Haas", {Dialect::Haas}},
  };  // FanucCorner tells the control (chooseMachine), Inch the units: neither a dialect
  return table;
}

const Admitting& admitting(EvidenceKind kind) {
  for (const Admitting& row : admittingTable())
    if (row.kind == kind) return row;
  return admittingTable().front();
}

bool admits(EvidenceKind kind, Dialect dialect) {
  const auto& dialects = admitting(kind).dialects;
  return std::find(dialects.begin(), dialects.end(), dialect) != dialects.end();
}

std::vector<EvidenceKind> kindsPresent(const MachineEvidence& evidence) {
  std::vector<EvidenceKind> kinds;
  for (const Admitting& row : admittingTable())
    if (evidence.count(row.kind) > 0) kinds.push_back(row.kind);
  return kinds;
}

// Each code the marks show, once, in the order first seen: a program with ten G94 facing
// blocks could not be told apart by one code, not by ten.
std::string marksText(const std::vector<EvidenceMark>& marks) {
  std::vector<std::string_view> named;
  std::string text;
  for (const EvidenceMark& m : marks) {
    if (std::find(named.begin(), named.end(), m.text) != named.end()) continue;
    named.push_back(m.text);
    text += (text.empty() ? "" : ", ") + m.text;
  }
  return text;
}

// The dialect every kind present admits (the first in kDialects' order), or nullopt.
std::optional<Dialect> admittedByAll(const std::vector<EvidenceKind>& kinds) {
  for (Dialect dialect : kDialects)
    if (std::all_of(kinds.begin(), kinds.end(), [&](EvidenceKind k) { return admits(k, dialect); })) return dialect;
  return std::nullopt;
}

void inferDialect(const MachineEvidence& evidence, MachineChoice& choice) {
  const std::vector<EvidenceKind> kinds = kindsPresent(evidence);
  choice.dialectInferred = true;
  if (const auto dialect = admittedByAll(kinds)) {
    choice.dialect = *dialect;
    for (EvidenceKind kind : kinds)
      for (const EvidenceMark& m : evidence.of(kind)) choice.because.push_back(markText(m));
    if (kinds.empty()) {
      // Thin evidence: said with the codes that could not be told apart.
      const std::string unclear = marksText(evidence.ambiguous);
      choice.because.push_back(fmt::format(
          "no code only one G-code system reads{}: the default, {}",
          unclear.empty() ? "" : " (" + unclear + ": a cycle in system A, a move in system B)", dialectName(*dialect)));
    }
    return;
  }
  // A conflict: one mark of each kind that no dialect admits together, the default kept.
  choice.dialect = Dialect::FanucA;
  for (std::size_t i = 0; i < kinds.size(); ++i)
    for (std::size_t j = i + 1; j < kinds.size(); ++j) {
      if (admittedByAll({kinds[i], kinds[j]})) continue;
      const EvidenceMark& a = evidence.of(kinds[i]).front();
      const EvidenceMark& b = evidence.of(kinds[j]).front();
      choice.conflicts.push_back(fmt::format("{} ({}) against {} ({})", markText(a), admitting(kinds[i]).name,
                                             markText(b), admitting(kinds[j]).name));
    }
  choice.because.push_back("the evidence conflicts: the default, fanuc-a");
  const EvidenceMark& at = evidence.of(kinds.front()).front();
  choice.warnings.push_back({at.line, at.column,
                             fmt::format("the program's codes belong to more than one G-code system ({}): read as "
                                         "fanuc-a, the default; give --dialect to say which",
                                         fmt::join(choice.conflicts, "; "))});
}

// A stated dialect the evidence contradicts: a warning at the first mark it does not admit.
void warnIfContradicted(const MachineEvidence& evidence, Dialect dialect, const std::string& by,
                        MachineChoice& choice) {
  for (EvidenceKind kind : kindsPresent(evidence)) {
    if (admits(kind, dialect)) continue;
    const EvidenceMark& m = evidence.of(kind).front();
    std::string readers;
    for (Dialect d : admitting(kind).dialects) readers += (readers.empty() ? "" : " or ") + std::string(dialectName(d));
    choice.warnings.push_back({m.line, m.column,
                               fmt::format("{} is {}'s ({}), but {} says {}: the statement wins", m.text,
                                           admitting(kind).name, readers, by, dialectName(dialect))});
    return;
  }
}

}  // namespace

std::optional<Dialect> dialectImpliedBy(std::string_view controlPreset) {
  for (const Pairing& p : kPairings)
    if (p.control == controlPreset) return p.dialect;
  return std::nullopt;
}

std::optional<std::string_view> controlImpliedBy(Dialect dialect) {
  for (const Pairing& p : kPairings)
    if (p.dialect == dialect) return p.control;
  return std::nullopt;
}

std::vector<Dialect> dialectsAdmitting(EvidenceKind kind) { return admitting(kind).dialects; }
std::string_view evidenceName(EvidenceKind kind) { return admitting(kind).name; }

std::string markText(const EvidenceMark& mark) { return fmt::format("{} at line {}", mark.text, mark.line); }

MachineChoice chooseMachine(const MachineEvidence& evidence, const MachineStatement& stated) {
  MachineChoice choice;
  // The dialect: stated, else implied by a stated control, else read from the program.
  if (stated.dialect) {
    choice.dialect = *stated.dialect;
    choice.because.push_back(fmt::format("{} {}", stated.dialectBy, dialectName(*stated.dialect)));
    warnIfContradicted(evidence, *stated.dialect, stated.dialectBy, choice);
  } else if (const auto implied = stated.control ? dialectImpliedBy(*stated.control) : std::nullopt) {
    choice.dialect = *implied;
    choice.because.push_back(fmt::format("{} {} (its dialect)", stated.controlBy, *stated.control));
    warnIfContradicted(evidence, *implied, stated.controlBy, choice);
  } else {
    inferDialect(evidence, choice);
  }
  // The control: stated, else implied by the dialect, else the trainers' when a trainer's
  // stock line or tool change is written, else Fanuc's when its corner words are, else the
  // default.
  if (stated.control) {
    choice.control = *stated.control;
    choice.because.push_back(fmt::format("{} {}", stated.controlBy, *stated.control));
  } else if (const auto implied = controlImpliedBy(choice.dialect)) {
    choice.control = std::string(*implied);
    choice.controlInferred = choice.dialectInferred;
  } else if (evidence.count(EvidenceKind::Trainer) > 0) {
    choice.control = "denford";
    choice.controlInferred = true;
    choice.because.push_back(markText(evidence.of(EvidenceKind::Trainer).front()) + " (a school trainer's)");
  } else if (evidence.count(EvidenceKind::FanucCorner) > 0) {
    choice.control = "fanuc-0i-t";
    choice.controlInferred = true;
    choice.because.push_back(markText(evidence.of(EvidenceKind::FanucCorner).front()) + " (Fanuc's corner word)");
  } else {
    choice.control = std::string(kDefaultControlPreset);
  }
  std::sort(choice.because.begin(), choice.because.end());
  choice.because.erase(std::unique(choice.because.begin(), choice.because.end()), choice.because.end());
  return choice;
}

std::string describeMachine(const MachineChoice& choice) {
  std::string text = fmt::format("dialect {}, control {}", dialectName(choice.dialect), choice.control);
  const bool stated = !choice.dialectInferred && !choice.controlInferred;
  text += stated ? ", as stated" : ", read from the program";
  if (!choice.because.empty()) text += fmt::format(" ({})", fmt::join(choice.because, ", "));
  if (!choice.conflicts.empty()) text += fmt::format("; conflicting: {}", fmt::join(choice.conflicts, "; "));
  return text;
}

std::vector<Error> lengthWarnings(const MachineEvidence& evidence, const ControlParameters& control,
                                  std::string_view controlPreset, double barDiameterMm) {
  std::vector<Error> warnings;
  if (control.decimalPointInput == DecimalPointInput::LeastIncrements && evidence.firstBareLength) {
    const LengthWord& w = *evidence.firstBareLength;
    const double asRead = w.value * control.leastIncrementMm;
    const bool beside = evidence.pointLengths > 0;
    const bool tooSmall = evidence.largestBareLength * control.leastIncrementMm < barDiameterMm / 20;
    if (beside || tooSmall)
      warnings.push_back({w.line, w.column,
                          fmt::format("{} has no decimal point: {} reads it in least increments, as {:g} mm ({}); "
                                      "write {}. for {:g} mm, or use --control gsk980tdi to read every bare number "
                                      "in mm",
                                      w.text, controlPreset, asRead,
                                      beside ? fmt::format("{} {} written without a point beside {} with one", evidence.bareLengths,
                                                           evidence.bareLengths == 1 ? "length is" : "lengths are",
                                                           evidence.pointLengths)
                                             : fmt::format("the largest such length is {:g} mm on a Φ{:g} bar",
                                                           evidence.largestBareLength * control.leastIncrementMm,
                                                           barDiameterMm),
                                      w.text, w.value)});
  }
  const bool unitsStated = evidence.count(EvidenceKind::Inch) > 0 || evidence.metricStated;
  if (!unitsStated && barDiameterMm >= 10 && evidence.largestPointLengthWord && evidence.pointLengths >= 3 &&
      evidence.largestPointLength < 1.0 && evidence.largestBareLength < 1.0) {
    const LengthWord& w = *evidence.largestPointLengthWord;
    warnings.push_back({w.line, w.column,
                        fmt::format("every length is under a millimetre (the largest, {}) on a Φ{:g} bar, and the "
                                    "program states no units: is it an inch program without its G20? read as mm",
                                    w.text, barDiameterMm)});
  }
  return warnings;
}

}  // namespace lathesim::interp
