#pragma once
// The repository's own C++ sources and their `#include "…"`s, read from the tree.

#include <filesystem>
#include <string>
#include <vector>

#include "tests/structure/include_rules.hpp"

namespace lathesim::structure {

/// The C++ files (.cpp .hpp .h .cc) under `root`, relative to it with '/', sorted. Hidden
/// folders, node_modules and build trees (a folder holding CMakeCache.txt) are not sources.
std::vector<std::string> sourceFiles(const std::filesystem::path& root);

/// The `#include "…"` lines of `files` that name a file of the repository, resolved as the
/// compiler does with the root on its include path: beside the including file first, then
/// from the root. Includes of files outside the tree (<…>, generated headers) are left out.
std::vector<Include> readIncludes(const std::filesystem::path& root, const std::vector<std::string>& files);

}  // namespace lathesim::structure
