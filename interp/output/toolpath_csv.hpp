#pragma once
// A Toolpath as CSV, for golden files and for people:
//   line,kind,x0,z0,x1,z1,feed,xc,zc,time_s,thread_deg,spindle
// one row per move; kind rapid, feed, cw, ccw (G02/G03), dwell or thread; x0/x1/xc are
// DIAMETERS (as programs write X), z in mm, feed in the move's feed mode unit (0 for rapids;
// a thread move's lead in mm/rev); xc,zc the centre of an arc (empty otherwise); time_s the
// move's machine time; thread_deg and spindle, for thread moves only, the spindle angle the
// move starts at (degrees from the one-revolution signal, in the direction the spindle
// turns: Q for a pass's first move) and that direction (cw for M03, ccw for M04). Numbers
// have at most 4 decimals, trailing zeros stripped. The first seven columns are a contract:
// later columns are only ever added after them, and the reader takes files with just those
// seven, or the first ten.

#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "interp/base/move.hpp"

namespace lathesim::interp {

struct CsvRow {
  int line = 0;
  std::string kind;  // "rapid", "feed", "cw", "ccw", "dwell" or "thread"
  double x0 = 0, z0 = 0, x1 = 0, z1 = 0;  // x as diameters, mm
  double feed = 0;
  std::optional<double> xc, zc;  // arcs: the centre, X as a diameter
  std::optional<double> timeS;   // absent in files with the first seven columns only
  std::optional<double> threadDeg;      // thread moves: the start angle (degrees)
  std::optional<std::string> spindle;   // thread moves: "cw" or "ccw"
};

/// Writes the header and one row per move, in order.
void writeToolpathCsv(const Toolpath& toolpath, std::ostream& out);

/// The header line and one move's row, each with its newline, for moves written as they
/// stream (interp/base/move_sink.hpp).
std::string toolpathCsvHeader();
std::string toolpathCsvRow(const Move& move);

/// Reads what writeToolpathCsv wrote. Throws std::runtime_error on a missing header or a
/// malformed row (golden files are trusted test input, so a bad one is a broken invariant).
std::vector<CsvRow> readToolpathCsv(std::istream& in);

/// A number with at most 4 decimals and no trailing zeros: 130, 62.5, 0.1, -110.
std::string csvNumber(double value);

}  // namespace lathesim::interp
