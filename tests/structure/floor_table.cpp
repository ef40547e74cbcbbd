#include "tests/structure/floor_table.hpp"

#include <sstream>
#include <stdexcept>

namespace lathesim::structure {

FloorTable readFloorTable(std::istream& in) {
  FloorTable table;
  std::string line;
  int lineNumber = 0;
  int floor = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.empty() || line.front() == '#') continue;
    if (line.front() == '[') {
      table.scopes.push_back({line.substr(1, line.find(']') - 1), {}});
      floor = 0;
      continue;
    }
    if (table.scopes.empty()) {
      throw std::runtime_error("floors line " + std::to_string(lineNumber) + ": folders before any [scope]");
    }
    std::istringstream folders(line);
    for (std::string folder; folders >> folder;) {
      if (!table.scopes.back().floorOf.emplace(folder, floor).second) {
        throw std::runtime_error("floors line " + std::to_string(lineNumber) + ": " + folder + " placed twice");
      }
    }
    ++floor;
  }
  return table;
}

std::optional<std::string> childOf(const FloorScope& scope, const std::string& file) {
  std::string inside = file;
  if (scope.folder != ".") {
    const std::string prefix = scope.folder + "/";
    if (file.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    inside = file.substr(prefix.size());
  }
  const auto slash = inside.find('/');
  if (slash == std::string::npos) return ".";
  return inside.substr(0, slash);
}

}  // namespace lathesim::structure
