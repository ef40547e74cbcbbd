// docs/codes.md is the interpreter's tables written out: it must be what the generator writes
// now, and what the generator writes must say what the interpreter reads.

#include "tests/docs/code_reference.hpp"
#include "tests/support/lathesim_process.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace lathesim::docs {
namespace {

using test::readFile;

// The lines of `section`: from its heading to the next heading of the same or a higher level.
std::string section(const std::string& text, const std::string& heading) {
  const std::size_t level = heading.find_first_not_of('#');
  std::istringstream lines(text);
  std::string line, found;
  bool inside = false;
  while (std::getline(lines, line)) {
    const std::size_t hashes = line.find_first_not_of('#');
    const bool isHeading = hashes > 0 && hashes != std::string::npos && line[hashes] == ' ';
    if (inside && isHeading && hashes <= level) break;
    if (line == heading) inside = true;
    if (inside) found += line + '\n';
  }
  return found;
}

bool has(const std::string& text, const std::string& row) { return text.find(row) != std::string::npos; }

TEST(CodeReference, DocsCodesMdIsWhatTheTablesSay) {
  const std::string path = LATHESIM_DOCS_DIR "/codes.md";
  const std::string written = readFile(path);
  // Compared whole (not with EXPECT_EQ on the strings, which would print two long files).
  EXPECT_TRUE(written == codeReference())
      << path << " differs from the interpreter's tables (interp/control/). Regenerate it from the "
      << "repository's folder:\n  " << kRegenerateCodeReference << "\nand commit it with the tables' change.";
}

// Each dialect's table names its own codes with the system-A meaning they stand for (the
// Fanuc 0i-T table of G-code systems A/B; the HNC-21T's G80/G81/G82): worked out from the
// controls' manuals, not from the table.
TEST(CodeReference, EachDialectWritesItsOwnCodes) {
  const std::string text = codeReference();
  const std::string a = section(text, "### Dialect `fanuc-a`");
  const std::string b = section(text, "### Dialect `fanuc-b`");
  const std::string hnc = section(text, "### Dialect `hnc`");
  const std::string haas = section(text, "### Dialect `haas`");
  ASSERT_FALSE(a.empty() || b.empty() || hnc.empty() || haas.empty()) << text;

  EXPECT_TRUE(has(a, "| G90 | axial cutting cycle | motion (group 01) | simulated |")) << a;
  EXPECT_TRUE(has(a, "| G94 | face cutting cycle | motion (group 01) | simulated |")) << a;
  EXPECT_FALSE(has(a, "| G77 |")) << a;

  EXPECT_TRUE(has(b, "| G77 | axial cutting cycle (fanuc-a G90) | motion (group 01) | simulated |")) << b;
  EXPECT_TRUE(has(b, "| G79 | face cutting cycle (fanuc-a G94) |")) << b;
  EXPECT_TRUE(has(b, "| G33 | thread cutting (fanuc-a G32) |")) << b;
  EXPECT_TRUE(has(b, "| G90 | absolute distance mode | distance mode (absolute/incremental) | simulated |")) << b;
  EXPECT_TRUE(has(b, "| G95 | feed per revolution (fanuc-a G99) |")) << b;
  EXPECT_FALSE(has(b, "| G32 |")) << "system B has no G32: " << b;

  EXPECT_TRUE(has(hnc, "| G80 | axial cutting cycle (fanuc-a G90) |")) << hnc;
  EXPECT_TRUE(has(hnc, "| G81 | face cutting cycle (fanuc-a G94) |")) << hnc;
  EXPECT_TRUE(has(hnc, "| G82 | threading cycle (fanuc-a G92) |")) << hnc;
  EXPECT_TRUE(has(hnc, "| G71 | OD/ID roughing cycle in hnc's one-block form | one-shot (group 00) | refused: not read yet |"))
      << hnc;
  EXPECT_TRUE(has(hnc, "| G76 | multiple threading cycle | one-shot (group 00) | simulated |")) << hnc;

  EXPECT_TRUE(has(haas, "| G71 | OD/ID roughing cycle | one-shot (group 00) | simulated |")) << haas;
  for (const std::string* table : {&a, &b, &hnc, &haas})
    EXPECT_TRUE(has(*table, "| G112 | polar coordinate interpolation | one-shot (group 00) | refused: needs a C axis"))
        << *table;
}

// The machine's own M codes are listed per control, under the control that takes them: Haas's
// M13 is its air jet (Haas lathe M-code list), the GSK980TDi's M12 its chuck clamp.
TEST(CodeReference, MachineMCodesAreListedPerControl) {
  const std::string text = codeReference();
  const std::string haas = section(text, "#### `m_codes = \"haas\"` (preset `haas`)");
  const std::string gsk = section(text, "#### `m_codes = \"gsk980tdi\"` (preset `gsk980tdi`)");
  ASSERT_FALSE(haas.empty() || gsk.empty()) << text;
  EXPECT_TRUE(has(haas, "| M13 | auto air jet off |")) << haas;
  EXPECT_TRUE(has(gsk, "| M12 | chuck clamp |")) << gsk;
  EXPECT_FALSE(has(gsk, "| M13 |")) << gsk;
  const std::string common = section(text, "### Every control");
  EXPECT_TRUE(has(common, "| M13 | live tool on")) << common;
  EXPECT_TRUE(has(common, "| refused: needs live tooling (a driven tool spindle) |")) << common;
  EXPECT_TRUE(has(common, "| M98 | subprogram call | subprogram | simulated |")) << common;
}

// Each preset's parameters with their values and manual references; an unchecked value is ⚠.
TEST(CodeReference, PresetsGiveEveryParameterWithItsReference) {
  const std::string text = codeReference();
  const std::string overview = section(text, "## Control presets");
  EXPECT_TRUE(has(overview, "| parameter | `gsk980tdi` | `fanuc-0i-t` | `haas` |")) << overview;
  EXPECT_TRUE(has(overview, "| `g28_tool_offset` | \"cancel\" | \"keep\" | \"keep\" |")) << overview;
  EXPECT_TRUE(has(overview, "| `g71_depth` | 1 ⚠ | 1 ⚠ | 2.54 ⚠ |")) << overview;
  const std::string gsk = section(text, "### Preset `gsk980tdi`");
  EXPECT_TRUE(has(gsk, "| `g04_p` | \"milliseconds\" | §3.14 (P in ms) |")) << gsk;
  EXPECT_TRUE(has(gsk, "| `g71_depth` | 1 | ⚠ GSK No.51; its factory value assumed |")) << gsk;
}

}  // namespace
}  // namespace lathesim::docs
