// The repository's own includes keep its floors (floors.txt; docs/design.md, "Floors"): no
// folder reaches up or sideways, every folder is placed, and no folders include each other
// in a cycle. A failure lists every include at fault with the rule it breaks.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "tests/structure/include_rules.hpp"
#include "tests/structure/source_includes.hpp"

namespace lathesim::structure {
namespace {

const std::filesystem::path kRoot = LATHESIM_SOURCE_DIR;

std::string listed(const std::vector<Violation>& violations) {
  std::string text;
  for (const Violation& violation : violations) text += describe(violation) + "\n";
  return text;
}

class RepositoryFloors : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::ifstream floorsFile(kRoot / "tests/structure/floors.txt");
    ASSERT_TRUE(floorsFile) << "tests/structure/floors.txt";
    floors_ = readFloorTable(floorsFile);
    files_ = sourceFiles(kRoot);
    includes_ = readIncludes(kRoot, files_);
  }
  static inline FloorTable floors_;
  static inline std::vector<std::string> files_;
  static inline std::vector<Include> includes_;
};

// The check reads the real tree: it finds the facade's include of the executor's runner, and
// an include resolved beside the including file.
TEST_F(RepositoryFloors, ReadsTheRepositorysIncludes) {
  ASSERT_GT(files_.size(), 200u);
  auto has = [&](const std::string& file, const std::string& target) {
    return std::any_of(includes_.begin(), includes_.end(),
                       [&](const Include& i) { return i.file == file && i.target == target; });
  };
  EXPECT_TRUE(has("interp/interpreter.cpp", "interp/execution/program_runner.hpp"));
  EXPECT_TRUE(has("tests/interp/text/typing_slips_test.cpp", "tests/interp/test_support.hpp"));
  EXPECT_TRUE(std::none_of(files_.begin(), files_.end(),
                           [](const std::string& f) { return f.rfind("build/", 0) == 0; }));
}

TEST_F(RepositoryFloors, EveryFolderHasAFloor) {
  const auto violations = unplacedFiles(files_, floors_);
  EXPECT_TRUE(violations.empty()) << listed(violations);
}

TEST_F(RepositoryFloors, NoIncludeReachesUpOrSideways) {
  const auto violations = floorViolations(includes_, floors_);
  EXPECT_TRUE(violations.empty()) << violations.size() << " includes break the floors:\n" << listed(violations);
}

TEST_F(RepositoryFloors, NoFoldersIncludeEachOtherInACycle) {
  const auto violations = folderCycles(includes_);
  EXPECT_TRUE(violations.empty()) << listed(violations);
}

}  // namespace
}  // namespace lathesim::structure
