// The repository's own C++ kept to sizes a reader can hold: no file over 700 lines and no
// function over 150 (issue 32). Data tables are excepted only by name, below, with why.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tests/structure/source_scanner.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::structure {
namespace {

namespace fs = std::filesystem;
using test::readFile;

constexpr int kMaxFileLines = 700;
constexpr int kMaxFunctionLines = 150;

/// Files allowed past the limits because they hold data, not logic: path (from the
/// repository's root) -> why. Keep it short; a table that grows belongs in a data file.
const std::map<std::string, std::string> kDataTables = {};

bool isSource(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".cpp" || ext == ".hpp" || ext == ".h" || ext == ".cc";
}

/// Every C++ source of the repository, relative to its root: build trees (a folder holding
/// CMakeCache.txt) and hidden folders left out.
std::vector<fs::path> ownSources(const fs::path& root) {
  std::vector<fs::path> sources;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& path = it->path();
    if (it->is_directory() && (path.filename().string().front() == '.' || fs::exists(path / "CMakeCache.txt"))) {
      it.disable_recursion_pending();
    } else if (it->is_regular_file() && isSource(path)) {
      sources.push_back(path.lexically_relative(root));
    }
  }
  return sources;
}

int lineCount(const std::string& text) {
  int lines = 0;
  for (const char c : text) lines += c == '\n';
  return lines + (!text.empty() && text.back() != '\n');
}

TEST(Sizes, TheSourceWalkFindsEveryModule) {
  std::map<std::string, int> perModule;
  for (const fs::path& path : ownSources(LATHESIM_SOURCE_DIR)) ++perModule[path.begin()->string()];
  for (const char* module : {"geometry", "interp", "sim", "render", "setup", "measure", "batch", "app", "tests"})
    EXPECT_GT(perModule[module], 0) << module;
  EXPECT_EQ(perModule.count("build"), 0u);
}

TEST(Sizes, NoFileOver700LinesAndNoFunctionOver150) {
  std::vector<std::string> over;
  for (const fs::path& path : ownSources(LATHESIM_SOURCE_DIR)) {
    if (kDataTables.count(path.generic_string()) != 0) continue;
    const std::string source = readFile(fs::path(LATHESIM_SOURCE_DIR) / path);
    const int lines = lineCount(source);
    if (lines > kMaxFileLines)
      over.push_back(path.generic_string() + ": " + std::to_string(lines) + " lines (at most " +
                     std::to_string(kMaxFileLines) + ")");
    for (const FunctionSpan& span : functionSpans(source))
      if (span.lines() > kMaxFunctionLines)
        over.push_back(path.generic_string() + ":" + std::to_string(span.firstLine) + ": " + span.name + " is " +
                       std::to_string(span.lines()) + " lines (at most " + std::to_string(kMaxFunctionLines) + ")");
  }
  std::string list;
  for (const std::string& line : over) list += "\n  " + line;
  EXPECT_TRUE(over.empty()) << over.size() << " over the limits:" << list;
}

TEST(Sizes, EveryExceptedTableStillExists) {
  for (const auto& [path, why] : kDataTables) EXPECT_TRUE(fs::exists(fs::path(LATHESIM_SOURCE_DIR) / path)) << path;
}

}  // namespace
}  // namespace lathesim::structure
