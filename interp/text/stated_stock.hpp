#pragma once
// The bar a program states for itself, as school trainers and shop comments do:
//   [BILLET X56.4 Z84          a trainer's billet line: X the diameter, Z the length
//   (STOCK D40 L80)            a comment opening with STOCK, BLANK, BAR, BILLET, RAW or
//   (BLANK DIA 40 LENGTH 80)   MATERIAL (or 毛坯) that gives a diameter (D, DIA, Ø, Φ) and a
//   (STOCK Ø40 X 80)           length (L, LG, LENGTH), or a diameter and a length as "40 X 80"
// Only a statement that gives both numbers counts; the first one in the text is taken.

#include <optional>
#include <string>
#include <string_view>

namespace lathesim::interp {

struct StatedStock {
  double diameterMm = 0;
  double lengthMm = 0;
  int line = 0;
  int column = 0;
  std::string text;  // the statement as written
};

/// The statement on line `lineNumber`, `line` as written (without its '\n'), if it makes one.
/// A program's first statement is found in the one walk of its lines that reads the machine's
/// evidence (MachineEvidence::stock, machine_evidence.hpp), for the job and batch alike.
std::optional<StatedStock> stockStatedOn(std::string_view line, int lineNumber);

}  // namespace lathesim::interp
