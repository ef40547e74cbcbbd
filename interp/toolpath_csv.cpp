#include "interp/toolpath_csv.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

constexpr const char* kHeader = "line,kind,x0,z0,x1,z1,feed";

}  // namespace

std::string csvNumber(double value) {
  std::string text = fmt::format("{:.4f}", value);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  if (text == "-0") text = "0";
  return text;
}

void writeToolpathCsv(const Toolpath& toolpath, std::ostream& out) {
  out << kHeader << '\n';
  for (const Move& move : toolpath.moves) {
    out << move.line << ',' << kindName(move.kind) << ',' << csvNumber(diameterOf(move.from))
        << ',' << csvNumber(move.from.y()) << ',' << csvNumber(diameterOf(move.to)) << ','
        << csvNumber(move.to.y()) << ',' << csvNumber(move.feed) << '\n';
  }
}

std::vector<CsvRow> readToolpathCsv(std::istream& in) {
  std::string text;
  if (!std::getline(in, text) || (text != kHeader && text != std::string(kHeader) + '\r')) {
    throw std::runtime_error(fmt::format("toolpath CSV: expected the header '{}'", kHeader));
  }
  std::vector<CsvRow> rows;
  int lineNumber = 1;
  while (std::getline(in, text)) {
    ++lineNumber;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream stream(text);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    if (fields.size() != 7 || (fields[1] != "rapid" && fields[1] != "feed")) {
      throw std::runtime_error(
          fmt::format("toolpath CSV line {}: expected 7 fields line,kind,x0,z0,x1,z1,feed with "
                      "kind rapid or feed, got '{}'",
                      lineNumber, text));
    }
    try {
      rows.push_back({std::stoi(fields[0]), fields[1], std::stod(fields[2]), std::stod(fields[3]),
                      std::stod(fields[4]), std::stod(fields[5]), std::stod(fields[6])});
    } catch (const std::logic_error&) {
      throw std::runtime_error(
          fmt::format("toolpath CSV line {}: a field is not a number: '{}'", lineNumber, text));
    }
  }
  return rows;
}

}  // namespace lathesim::interp
