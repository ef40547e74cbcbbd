#pragma once
// A small C++ source scanner for the size check: it finds each top-level function body by
// matching braces, with comments, string and character literals and preprocessor lines blanked
// first so that a brace inside them does not count. It is not a parser: it knows namespaces,
// classes (whose member functions it measures one by one), enums, initialised data and
// constructor initialiser lists, which is all the project's own code needs.

#include <string>
#include <vector>

namespace lathesim::structure {

/// `source` with every comment, string literal (raw ones included), character literal and
/// preprocessor line replaced by spaces; newlines are kept, so line numbers stay true.
std::string blankCommentsAndLiterals(const std::string& source);

/// One function body, from the line of its opening brace to the line of its closing one
/// (1-based, both included). A lambda is part of the function it is written in; a lambda
/// initialising a variable outside any function is a function of its own, named by the variable.
struct FunctionSpan {
  std::string name;  // the (qualified) name before the parameter list, as written
  int firstLine = 0;
  int lastLine = 0;
  int lines() const { return lastLine - firstLine + 1; }
};

/// Every top-level function body in `source`: free functions, member functions defined in a
/// class body or outside it, at any depth of namespaces and classes.
std::vector<FunctionSpan> functionSpans(const std::string& source);

}  // namespace lathesim::structure
