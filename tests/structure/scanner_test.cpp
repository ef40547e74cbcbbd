// The size check's scanner on sources written for it: its measure must be right before the
// repository's sizes mean anything.

#include <gtest/gtest.h>

#include <string>

#include "tests/structure/source_scanner.hpp"

namespace lathesim::structure {
namespace {

/// A function `name` whose body spans `lines` lines, braces included.
std::string functionOf(const std::string& name, int lines) {
  std::string text = "int " + name + "(int x) {\n";
  for (int i = 0; i < lines - 2; ++i) text += "  x += " + std::to_string(i) + ";\n";
  return text + "}\n";
}

TEST(SourceScanner, MeasuresAFunctionFromItsOpeningBraceToItsClosingOne) {
  for (const int lines : {1, 2, 3, 150, 151, 400}) {
    const std::string source = lines == 1 ? "int f(int x) { return x; }\n" : functionOf("f", lines);
    const auto spans = functionSpans("// header\n\n" + source);
    ASSERT_EQ(spans.size(), 1u) << lines;
    EXPECT_EQ(spans[0].name, "f");
    EXPECT_EQ(spans[0].firstLine, 3);
    EXPECT_EQ(spans[0].lines(), lines);
  }
}

TEST(SourceScanner, IgnoresBracesInCommentsStringsCharactersAndDirectives) {
  const std::string source =
      "#define OPEN {\n"
      "#define LONG \\\n"
      "  {\n"
      "int f() {\n"
      "  // a } in a comment\n"
      "  /* and { in a block\n"
      "     comment } */\n"
      "  const char* s = \"}\\\"}\";\n"
      "  const char* raw = R\"x(} )\" {)x\";\n"
      "  char c = '}', d = '\\'', e = '{';\n"
      "  int n = 1'000'000;\n"
      "  return '}';\n"
      "}\n"
      "int g() { return 0; }\n";
  const auto spans = functionSpans(source);
  ASSERT_EQ(spans.size(), 2u);  // a brace in the continued #define would swallow f
  EXPECT_EQ(spans[0].name, "f");
  EXPECT_EQ(spans[0].firstLine, 4);
  EXPECT_EQ(spans[0].lastLine, 13);
  EXPECT_EQ(spans[1].name, "g");
  EXPECT_EQ(spans[1].firstLine, 14);
}

TEST(SourceScanner, BlankingKeepsEveryLineAndTheCodeAroundIt) {
  const std::string source = "a /* x\ny */ b \"s{\" 'c' // z\n#include <q>\nR\"(r\n)\" u8'{' 0x1'F";
  const std::string blanked = blankCommentsAndLiterals(source);
  EXPECT_EQ(blanked.size(), source.size());
  EXPECT_EQ(blanked, "a     \n     b              \n            \nR   \n   u8    0x1'F");
}

TEST(SourceScanner, MeasuresMemberFunctionsOfNestedClassesAndNotTheClassesThemselves) {
  const std::string source =
      "namespace outer { namespace {\n"
      "template <typename T = int>\n"
      "class Box : public Base<T> {\n"
      " public:\n"
      "  struct Inner {\n"
      "    int get() const {\n"
      "      return 1;\n"
      "    }\n"
      "  };\n"
      "  Box() : a_{1}, b_(2),\n"
      "        c_{3} {\n"
      "    a_ += 1;\n"
      "  }\n"
      "  bool operator==(const Box& o) const { return a_ == o.a_; }\n"
      "  std::vector<int> table_{1, 2, 3};\n"
      "  enum class Kind { A, B };\n"
      " private:\n"
      "  int a_, b_, c_;\n"
      "};\n"
      "}  // namespace\n"
      "extern \"C\" {\n"
      "void Box::Inner::reset() {\n"
      "  auto twice = [](int v) {\n"
      "    return 2 * v;\n"
      "  };\n"
      "  struct Local { int f() { return 0; } };\n"
      "}\n"
      "}\n"
      "const int kTable[] = {\n"
      "  1, 2,\n"
      "}, kOther[] = {3};\n"
      "const auto kSquare = [](int v) {\n"
      "  return v * v;\n"
      "};\n"
      "template <int N = 3, typename = Check<(N > 0)>>\n"
      "int size() { return N; }\n"
      "}  // namespace outer\n";
  const auto spans = functionSpans(source);
  ASSERT_EQ(spans.size(), 6u);
  EXPECT_EQ(spans[0].name, "get");
  EXPECT_EQ(spans[0].firstLine, 6);
  EXPECT_EQ(spans[0].lastLine, 8);
  EXPECT_EQ(spans[1].name, "Box");  // the initialiser list's braces belong to the constructor
  EXPECT_EQ(spans[1].firstLine, 10);
  EXPECT_EQ(spans[1].lastLine, 13);
  EXPECT_EQ(spans[2].name, "operator==");
  EXPECT_EQ(spans[2].lines(), 1);
  EXPECT_EQ(spans[3].name, "Box::Inner::reset");  // its lambda and local class are part of it
  EXPECT_EQ(spans[3].firstLine, 22);
  EXPECT_EQ(spans[3].lastLine, 27);
  EXPECT_EQ(spans[4].name, "kSquare");
  EXPECT_EQ(spans[4].firstLine, 32);
  EXPECT_EQ(spans[4].lastLine, 34);
  EXPECT_EQ(spans[5].name, "size");  // the template's '=' is no initialiser
  EXPECT_EQ(spans[5].firstLine, 36);
}

}  // namespace
}  // namespace lathesim::structure
