#pragma once
// ISO 1832 indexable insert designations (CNMG120408, TBHG120408, RCMT1204M0, …): the
// nominal geometry a simulator needs. Reference: ../shared/spec/iso-tools.md §1.
//
//   C N M G 12 04 08 [E] [R] [-maker suffix]
//   1 2 3 4  5  6  7  8   9
//   shape, clearance, tolerance class, hole/chipbreaker type, size, thickness, corner,
//   optional edge condition and hand; anything after a dash is the maker's and is ignored.

#include <string>
#include <string_view>

#include "geometry/iso_code.hpp"

namespace lathesim {

struct IsoInsert {
  std::string code;             // as given (upper case)
  char shape = 'C';             // position 1
  double noseAngleDeg = 80.0;   // ε of the cutting corners; 0 for a round insert
  char clearance = 'N';         // position 2 letter
  double clearanceDeg = 0.0;    // its angle (O "other": 0, described separately)
  char tolerance = 'M';         // position 3 letter, stored only (nominal sizes are simulated)
  char type = 'G';              // position 4 letter
  std::string sizeCode;         // position 5, e.g. "12", "S4"
  double inscribedCircleMm = 0; // IC d; for a round insert its diameter
  double edgeLengthMm = 0;      // theoretical (sharp-corner) edge length l; round: d
  double thicknessMm = 0;       // position 6
  double noseRadiusMm = 0;      // position 7; round inserts: d/2 (the whole insert is the nose)
  bool vendorSpecialSize = false;  // the size code is not in the inch IC series (see parseIsoInsert)
  char edgeCondition = 0;       // position 8 (F E T S K P) or 0
  char hand = 0;                // position 9 (R L N) or 0

  bool round() const { return shape == 'R'; }
};

/// Reads an ISO 1832 designation (case-insensitive, no spaces). Sizes come from a lookup
/// table keyed by (shape, size code) over the inch IC series (C12 → 12.70, T16 → 9.525,
/// W08 → 12.70, R12 with corner 00 → 12.70; with corner M0 the round's digits are its metric
/// diameter). A two-digit size that is not in the table is read as a vendor special: the
/// digits are the edge length in mm and IC = l / factor(shape) — TBHG120408's "12" gives
/// l = 12, d = 12/√3 = 6.928 — with a warning. Parallelogram and rectangle shapes (A B K L)
/// have no inscribed circle and are refused.
ParsedCode<IsoInsert> parseIsoInsert(std::string_view code);

/// l / d for a shape with an inscribed circle (§1.5): the edge length per mm of IC.
double edgeLengthPerInscribedMm(char shape);

}  // namespace lathesim
