// The structure check itself, on synthetic includes: an include down a floor passes; one up a
// floor, one to a neighbour on the same floor, a file in an unplaced folder and a cycle between
// folders are each caught and named.

#include <gtest/gtest.h>

#include <sstream>

#include "tests/structure/include_rules.hpp"

namespace lathesim::structure {
namespace {

FloorTable table() {
  std::istringstream text(
      "# comment\n"
      "[.]\n"
      "geometry\n"
      "interp\n"
      "sim render\n"
      "\n"
      "[interp]\n"
      "base\n"
      "text contour\n"
      "cycles\n"
      ".\n");
  return readFloorTable(text);
}

TEST(FloorTable, ReadsScopesAndFloorsBottomFirst) {
  const FloorTable floors = table();
  ASSERT_EQ(floors.scopes.size(), 2u);
  EXPECT_EQ(floors.scopes[0].folder, ".");
  EXPECT_EQ(floors.scopes[0].floorOf.at("geometry"), 0);
  EXPECT_EQ(floors.scopes[0].floorOf.at("sim"), 2);
  EXPECT_EQ(floors.scopes[0].floorOf.at("render"), 2);
  EXPECT_EQ(floors.scopes[1].folder, "interp");
  EXPECT_EQ(floors.scopes[1].floorOf.at("contour"), 1);
  EXPECT_EQ(floors.scopes[1].floorOf.at("."), 3);
}

TEST(FloorTable, RefusesAFolderPlacedTwiceAndFoldersBeforeAScope) {
  std::istringstream twice("[.]\nsim\ngeometry sim\n");
  EXPECT_THROW(readFloorTable(twice), std::runtime_error);
  std::istringstream early("sim\n[.]\n");
  EXPECT_THROW(readFloorTable(early), std::runtime_error);
}

TEST(FloorTable, ChildOfAFileInAScope) {
  const FloorTable floors = table();
  EXPECT_EQ(childOf(floors.scopes[1], "interp/base/move.hpp"), "base");
  EXPECT_EQ(childOf(floors.scopes[1], "interp/interpreter.hpp"), ".");
  EXPECT_EQ(childOf(floors.scopes[1], "sim/simulate.hpp"), std::nullopt);
  EXPECT_EQ(childOf(floors.scopes[1], "interpreter/x.hpp"), std::nullopt);  // not inside interp/
  EXPECT_EQ(childOf(floors.scopes[0], "interp/base/move.hpp"), "interp");
}

TEST(FloorViolations, IncludesDownAFloorOrInsideTheirFolderPass) {
  const std::vector<Include> includes{
      {"interp/cycles/g90.cpp", 3, "interp/base/move.hpp"},          // down two floors
      {"interp/cycles/g90.cpp", 4, "interp/cycles/g90.hpp"},         // its own folder
      {"interp/interpreter.cpp", 5, "interp/cycles/g90.hpp"},        // the facade, on top
      {"sim/sweep.cpp", 6, "interp/interpreter.hpp"},                // module down a floor
      {"interp/text/lexer.cpp", 7, "geometry/arc.hpp"},             // interp stands on geometry
  };
  EXPECT_TRUE(floorViolations(includes, table()).empty());
}

TEST(FloorViolations, AnIncludeUpAFloorIsNamedWithItsFileAndRule) {
  const std::vector<Include> includes{{"interp/base/move.hpp", 12, "interp/cycles/g90.hpp"}};
  const auto violations = floorViolations(includes, table());
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].file, "interp/base/move.hpp");
  EXPECT_EQ(violations[0].line, 12);
  EXPECT_EQ(violations[0].target, "interp/cycles/g90.hpp");
  EXPECT_EQ(describe(violations[0]),
            "interp/base/move.hpp:12: #include \"interp/cycles/g90.hpp\": interp/base/ reaches up to "
            "interp/cycles/ (floor 0 includes floor 2 in floors.txt's [interp])");
}

TEST(FloorViolations, AnIncludeOfTheFacadeFromBelowIsUpward) {
  const auto violations = floorViolations({{"interp/cycles/g90.hpp", 8, "interp/interpreter.hpp"}}, table());
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_NE(violations[0].rule.find("reaches up to interp/ (its own files)"), std::string::npos) << violations[0].rule;
}

TEST(FloorViolations, ModulesAreCheckedAtTheRoot) {
  const auto violations = floorViolations({{"interp/text/lexer.cpp", 2, "sim/voxels.hpp"}}, table());
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_NE(violations[0].rule.find("interp/ reaches up to sim/ (floor 1 includes floor 2 in floors.txt's [.])"),
            std::string::npos)
      << violations[0].rule;
}

TEST(FloorViolations, ANeighbourOnTheSameFloorIsRefusedBothWays) {
  const std::vector<Include> includes{{"interp/text/lexer.hpp", 1, "interp/contour/contour.hpp"},
                                      {"sim/sweep.hpp", 2, "render/mesh.hpp"}};
  const auto violations = floorViolations(includes, table());
  ASSERT_EQ(violations.size(), 2u);
  EXPECT_NE(violations[0].rule.find("includes its neighbour interp/contour/ on the same floor"), std::string::npos)
      << violations[0].rule;
  EXPECT_NE(violations[1].rule.find("sim/ includes its neighbour render/"), std::string::npos) << violations[1].rule;
}

TEST(UnplacedFiles, AFolderTheTableDoesNotPlaceIsNamed) {
  const auto violations = unplacedFiles({"interp/base/move.hpp", "interp/spool/file.hpp", "viewer/x.hpp"}, table());
  ASSERT_EQ(violations.size(), 2u);
  EXPECT_EQ(violations[0].file, "interp/spool/file.hpp");
  EXPECT_EQ(violations[0].rule, "interp/spool/ has no floor in floors.txt's [interp]: place it");
  EXPECT_EQ(violations[1].file, "viewer/x.hpp");
  EXPECT_EQ(violations[1].rule, "viewer/ has no floor in floors.txt's [.]: place it");
}

TEST(FolderCycles, NoneWhenIncludesGoOneWay) {
  const std::vector<Include> includes{{"a/x.cpp", 1, "b/y.hpp"}, {"b/y.hpp", 1, "c/z.hpp"}, {"a/x.cpp", 2, "c/z.hpp"},
                                      {"c/z.cpp", 1, "c/z.hpp"}};
  EXPECT_TRUE(folderCycles(includes).empty());
}

TEST(FolderCycles, TwoFoldersIncludingEachOtherAreOneCycle) {
  const std::vector<Include> includes{{"tests/a/x.cpp", 4, "tests/b/y.hpp"}, {"tests/b/y.cpp", 9, "tests/a/z.hpp"},
                                      {"tests/b/w.cpp", 2, "tests/a/z.hpp"}};
  const auto violations = folderCycles(includes);
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(describe(violations[0]),
            "tests/a/x.cpp:4: #include \"tests/b/y.hpp\": folders include each other in a cycle: tests/a -> "
            "tests/b (tests/a/x.cpp:4) -> tests/a (tests/b/y.cpp:9)");
}

TEST(FolderCycles, ALongerCycleIsFollowedRound) {
  const std::vector<Include> includes{{"a/x.cpp", 1, "b/y.hpp"}, {"b/y.hpp", 2, "c/z.hpp"}, {"c/z.hpp", 3, "a/w.hpp"},
                                      {"d/v.cpp", 4, "a/x.hpp"}};
  const auto violations = folderCycles(includes);
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_NE(violations[0].rule.find("a -> b (a/x.cpp:1) -> c (b/y.hpp:2) -> a (c/z.hpp:3)"), std::string::npos)
      << violations[0].rule;
}

}  // namespace
}  // namespace lathesim::structure
