#pragma once
// The floors of the repository's folders as floors.txt states them: for a scope (the
// repository, "." , or a folder such as "interp"), the folders directly inside it, bottom
// floor first.

#include <istream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lathesim::structure {

struct FloorScope {
  std::string folder;                      // "." for the repository's root, else e.g. "interp"
  std::map<std::string, int> floorOf;      // child folder ("." the scope's own files) → floor, 0 lowest
};

struct FloorTable {
  std::vector<FloorScope> scopes;
};

/// Reads the format of floors.txt. Throws std::runtime_error naming the line of a child
/// before any [scope] or of a folder placed twice in a scope.
FloorTable readFloorTable(std::istream& in);

/// Where `file` (a path relative to the repository's root, '/'-separated) stands in `scope`:
/// the child folder it lies in ("." for a file of the scope's own folder), or nothing when the
/// file is not inside the scope.
std::optional<std::string> childOf(const FloorScope& scope, const std::string& file);

}  // namespace lathesim::structure
