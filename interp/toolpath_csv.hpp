#pragma once
// A Toolpath as CSV, for golden files and for people:
//   line,kind,x0,z0,x1,z1,feed
// one row per move; x0/x1 are DIAMETERS (as programs write X), z in mm, feed in the move's
// feed mode unit (0 for rapids); numbers have at most 4 decimals, trailing zeros stripped.

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "interp/move.hpp"

namespace lathesim::interp {

struct CsvRow {
  int line = 0;
  std::string kind;  // "rapid" or "feed"
  double x0 = 0, z0 = 0, x1 = 0, z1 = 0;  // x as diameters, mm
  double feed = 0;
};

/// Writes the header and one row per move, in order.
void writeToolpathCsv(const Toolpath& toolpath, std::ostream& out);

/// Reads what writeToolpathCsv wrote. Throws std::runtime_error on a missing header or a
/// malformed row (golden files are trusted test input, so a bad one is a broken invariant).
std::vector<CsvRow> readToolpathCsv(std::istream& in);

/// A number with at most 4 decimals and no trailing zeros: 130, 62.5, 0.1, -110.
std::string csvNumber(double value);

}  // namespace lathesim::interp
