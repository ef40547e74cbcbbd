// The bad-program corpus: each tests/interp/bad/*.nc opens with the diagnostic it must give,
//   (expect: LINE:COL: error: part of the message)
// and interpreting it must give exactly that error, located in that file. The line is a
// comment to the interpreter too, so the expected text cannot contain a parenthesis. A
// second line "(control: PRESET; …)" names the control preset the program is bad on (else the
// default preset's), and a line "(dialect: NAME; …)" the dialect (else fanuc-a).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "interp/control/control_preset.hpp"
#include "interp/interpreter.hpp"
#include "test_support.hpp"
#include "tests/support/files.hpp"

namespace lathesim::interp {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> badPrograms() {
  std::vector<fs::path> paths;
  for (const auto& entry : fs::directory_iterator(LATHESIM_INTERP_BAD_DIR)) {
    if (entry.path().extension() == ".nc") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

using lathesim::test::readFile;

TEST(BadCorpus, HasAtLeastTwelvePrograms) { EXPECT_GE(badPrograms().size(), 12u); }

TEST(BadCorpus, EachProgramGivesItsExpectedDiagnostic) {
  const std::regex expectLine(R"(^\(expect: (\d+):(\d+): error: (.*)\)\r?$)");
  for (const fs::path& path : badPrograms()) {
    SCOPED_TRACE(path.filename().string());
    const std::string text = readFile(path);
    const std::string first = text.substr(0, text.find('\n'));
    std::smatch match;
    ASSERT_TRUE(std::regex_match(first, match, expectLine)) << "first line: " << first;
    const int line = std::stoi(match[1]);
    const int column = std::stoi(match[2]);
    const std::string part = match[3];

    const std::string name = path.filename().string();
    InterpreterOptions options = test::defaultOptions();
    const std::regex controlLine(R"(\n\(control: ([a-z0-9-]+);)");
    if (std::smatch control; std::regex_search(text, control, controlLine)) {
      const auto preset = controlPreset(control[1].str());
      ASSERT_TRUE(preset) << control[1];
      options.control = preset->parameters;
    }
    const std::regex dialectLine(R"(\n\(dialect: ([a-z0-9-]+);)");
    if (std::smatch dialect; std::regex_search(text, dialect, dialectLine)) {
      const auto named = dialectNamed(dialect[1].str());
      ASSERT_TRUE(named) << dialect[1];
      options.dialect = *named;
    }
    options.programDirectories = {path.parent_path()};  // subprograms kept beside the program
    const auto result = interpret(text, name, options);
    test::expectError(result, line, column, part);
    if (result.diagnostics.empty()) continue;
    const std::string shown = format(result.diagnostics[0]);
    const std::string location = name + ":" + std::to_string(line) + ":" +
                                 std::to_string(column) + ": error: ";
    EXPECT_EQ(shown.rfind(location, 0), 0u) << shown;
  }
}

}  // namespace
}  // namespace lathesim::interp
