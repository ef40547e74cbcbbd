#pragma once
// The machine a program is run on — its dialect and its control preset, one choice — from what
// the user stated (--dialect/--control, the setup's [machine] dialect and [control] name) and,
// for what was not stated, from the program's own evidence (interp/text/machine_evidence.hpp),
// by the rules of lathe-gcode.md "Reading the dialect from the program":
//   - a stated dialect or control always wins; one the evidence contradicts gets a warning
//     at the line that contradicts it;
//   - a dialect or control implies the other where the table below says so (haas ↔ haas);
//   - each kind of evidence admits some dialects; the dialect is the first of fanuc-a,
//     fanuc-b, hnc, haas that every kind present admits; when no dialect is admitted by all
//     the evidence conflicts: reported with one mark of each kind, the default kept; with no
//     evidence the default is taken, saying which codes could not be told apart;
//   - the control is, unless stated or implied, denford when the program writes a school
//     trainer's `[BILLET` line or M06 beside its T word, fanuc-0i-t when it writes Fanuc's ,C
//     or ,R corner words, else the default (gsk980tdi).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/control/control_parameters.hpp"
#include "interp/control/dialect.hpp"
#include "interp/base/result.hpp"
#include "interp/text/machine_evidence.hpp"

namespace lathesim::interp {

/// What the user said of the machine, and where ("--dialect", "the setup's [machine] dialect").
struct MachineStatement {
  std::optional<Dialect> dialect;
  std::string dialectBy;
  std::optional<std::string> control;  // a preset's name
  std::string controlBy;
};

struct MachineChoice {
  Dialect dialect = Dialect::FanucA;
  std::string control;
  bool dialectInferred = false;  // read from the program, not stated nor implied by a statement
  bool controlInferred = false;
  std::vector<std::string> because;    // "G95 at line 11", "--dialect fanuc-b"
  std::vector<std::string> conflicts;  // "G99 at line 3 (system A) against G95 at line 11 (system B)"
  std::vector<Error> warnings;         // located in the program
  bool inferred() const { return dialectInferred || controlInferred; }
};

/// The dialect a control implies, or nullopt (it reads more than one).
std::optional<Dialect> dialectImpliedBy(std::string_view controlPreset);
/// The control a dialect implies, or nullopt (more than one control writes it).
std::optional<std::string_view> controlImpliedBy(Dialect dialect);

/// The dialects a kind of dialect evidence (system A or B, HNC, Haas) admits, and what the
/// kind is called ("system B").
std::vector<Dialect> dialectsAdmitting(EvidenceKind kind);
std::string_view evidenceName(EvidenceKind kind);

/// "G95 at line 11".
std::string markText(const EvidenceMark& mark);

MachineChoice chooseMachine(const MachineEvidence& evidence, const MachineStatement& stated);

/// The choice in a few words, for a summary line: "dialect fanuc-b, control gsk980tdi, read
/// from the program (G95 at line 11, G92 S2500 at line 5)".
std::string describeMachine(const MachineChoice& choice);

/// Warnings of the lengths against the bar once the control is known: lengths without a
/// decimal point that `control` reads as least increments beside lengths with one, or that
/// read so are far too small for the bar; every length under a millimetre on a bar of 10 mm or
/// more with no G20/G21 (an inch program without its G20).
std::vector<Error> lengthWarnings(const MachineEvidence& evidence, const ControlParameters& control,
                                  std::string_view controlPreset, double barDiameterMm);

}  // namespace lathesim::interp
