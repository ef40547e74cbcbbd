#include "interp/output/toolpath_csv.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

constexpr std::string_view kContractHeader = "line,kind,x0,z0,x1,z1,feed";
constexpr std::string_view kTimedHeader = "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s";
constexpr std::string_view kHeader = "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s,thread_deg,spindle";

bool knownKind(const std::string& kind) {
  for (MoveKind k : {MoveKind::Rapid, MoveKind::Feed, MoveKind::ArcCW, MoveKind::ArcCCW, MoveKind::Dwell, MoveKind::Thread})
    if (kind == kindName(k)) return true;
  return false;
}

std::optional<double> optionalNumber(const std::string& field) {
  if (field.empty()) return std::nullopt;
  return std::stod(field);
}

}  // namespace

std::string csvNumber(double value) {
  std::string text = fmt::format("{:.4f}", value);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  if (text == "-0") text = "0";
  return text;
}

std::string toolpathCsvHeader() { return std::string(kHeader) + '\n'; }

std::string toolpathCsvRow(const Move& move) {
  std::string row = fmt::format("{},{},{},{},{},{},{},", move.line, kindName(move.kind), csvNumber(diameterOf(move.from)),
                                csvNumber(move.from.y()), csvNumber(diameterOf(move.to)), csvNumber(move.to.y()),
                                csvNumber(move.feed));
  if (isArc(move.kind)) row += csvNumber(diameterOf(move.center)) + ',' + csvNumber(move.center.y());
  else row += ',';
  row += ',' + csvNumber(move.timeS) + ',';
  if (move.kind == MoveKind::Thread)
    row += csvNumber(move.thread.startAngleDeg) + ',' + (move.spindleDirection == SpindleDirection::Clockwise ? "cw" : "ccw");
  else
    row += ',';
  row += '\n';
  return row;
}

void writeToolpathCsv(const Toolpath& toolpath, std::ostream& out) {
  out << toolpathCsvHeader();
  for (const Move& move : toolpath.moves) out << toolpathCsvRow(move);
}

std::vector<CsvRow> readToolpathCsv(std::istream& in) {
  std::string text;
  if (std::getline(in, text) && !text.empty() && text.back() == '\r') text.pop_back();
  const bool threads = text == kHeader;
  const bool full = threads || text == kTimedHeader;
  if (!full && text != kContractHeader) {
    throw std::runtime_error(fmt::format(
        "toolpath CSV: expected the header '{}' (or its first ten or seven columns)", kHeader));
  }
  const std::size_t columns = threads ? 12 : full ? 10 : 7;
  std::vector<CsvRow> rows;
  int lineNumber = 1;
  while (std::getline(in, text)) {
    ++lineNumber;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream stream(text);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    if (!text.empty() && text.back() == ',') fields.emplace_back();  // getline drops a last empty field
    if (fields.size() != columns || !knownKind(fields[1])) {
      throw std::runtime_error(fmt::format(
          "toolpath CSV line {}: expected {} fields as in the header, with kind rapid, feed, cw, ccw, dwell or "
          "thread, "
          "got '{}'",
          lineNumber, columns, text));
    }
    try {
      CsvRow row;
      row.line = std::stoi(fields[0]);
      row.kind = fields[1];
      row.x0 = std::stod(fields[2]);
      row.z0 = std::stod(fields[3]);
      row.x1 = std::stod(fields[4]);
      row.z1 = std::stod(fields[5]);
      row.feed = std::stod(fields[6]);
      if (full) {
        row.xc = optionalNumber(fields[7]);
        row.zc = optionalNumber(fields[8]);
        row.timeS = optionalNumber(fields[9]);
      }
      if (threads) {
        row.threadDeg = optionalNumber(fields[10]);
        if (!fields[11].empty()) row.spindle = fields[11];
      }
      rows.push_back(row);
    } catch (const std::logic_error&) {
      throw std::runtime_error(
          fmt::format("toolpath CSV line {}: a field is not a number: '{}'", lineNumber, text));
    }
  }
  return rows;
}

}  // namespace lathesim::interp
