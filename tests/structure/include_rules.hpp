#pragma once
// The rules the repository's includes keep, as pure functions over (file, include) pairs:
// no folder includes one on a higher floor or a neighbour on its own floor (floors.txt), and no
// folders include each other in a cycle. Paths are relative to the repository's root.

#include <string>
#include <vector>

#include "tests/structure/floor_table.hpp"

namespace lathesim::structure {

struct Include {
  std::string file;    // the including file
  int line = 0;        // of the #include in it
  std::string target;  // the file it includes
};

struct Violation {
  std::string file;
  int line = 0;        // 0: the file as a whole
  std::string target;  // the include at fault; empty for a file the table does not place
  std::string rule;    // the rule broken, in words
};

/// "file:line: #include "target": rule"
std::string describe(const Violation& violation);

/// Every include that reaches up a floor or sideways to a neighbour, in any scope of `table`.
std::vector<Violation> floorViolations(const std::vector<Include>& includes, const FloorTable& table);

/// Every file in a scope's folder whose child folder the table does not place.
std::vector<Violation> unplacedFiles(const std::vector<std::string>& files, const FloorTable& table);

/// One violation for each set of folders (the folder of a file is its directory) that include
/// each other round in a cycle, naming the cycle and an include for each of its steps.
std::vector<Violation> folderCycles(const std::vector<Include>& includes);

}  // namespace lathesim::structure
