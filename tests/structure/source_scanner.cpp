#include "tests/structure/source_scanner.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string_view>

namespace lathesim::structure {
namespace {

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Replaces text[from, to) with spaces, keeping its newlines.
void blank(std::string& text, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to && i < text.size(); ++i)
    if (text[i] != '\n') text[i] = ' ';
}

/// The end of the literal opened by the quote at `open` (one past its closing quote); a
/// backslash escapes the next character.
std::size_t quotedEnd(const std::string& text, std::size_t open) {
  const char quote = text[open];
  std::size_t i = open + 1;
  while (i < text.size() && text[i] != quote && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
  return std::min(i + 1, text.size());
}

/// The end of the raw string R"delim( ... )delim" whose quote is at `open`.
std::size_t rawStringEnd(const std::string& text, std::size_t open) {
  const std::size_t paren = text.find('(', open);
  if (paren == std::string::npos) return text.size();
  std::string closing(1, ')');
  closing.append(text, open + 1, paren - open - 1).push_back('"');
  const std::size_t close = text.find(closing, paren);
  return close == std::string::npos ? text.size() : close + closing.size();
}

/// The end of the preprocessor directive starting at `hash`: its line and every line a
/// trailing backslash continues it onto.
std::size_t directiveEnd(const std::string& text, std::size_t hash) {
  std::size_t i = hash;
  for (;;) {
    const std::size_t newline = text.find('\n', i);
    if (newline == std::string::npos) return text.size();
    std::size_t last = newline;
    while (last > i && (text[last - 1] == ' ' || text[last - 1] == '\r')) --last;
    if (last == i || text[last - 1] != '\\') return newline;
    i = newline + 1;
  }
}

bool startsLine(const std::string& text, std::size_t pos) {
  while (pos > 0 && (text[pos - 1] == ' ' || text[pos - 1] == '\t')) --pos;
  return pos == 0 || text[pos - 1] == '\n';
}

}  // namespace

std::string blankCommentsAndLiterals(const std::string& source) {
  std::string text = source;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    std::size_t end = i;
    if (c == '#' && startsLine(text, i)) {
      end = directiveEnd(text, i);
    } else if (c == '/' && next == '/') {
      end = std::min(text.find('\n', i), text.size());
    } else if (c == '/' && next == '*') {
      const std::size_t close = text.find("*/", i + 2);
      end = close == std::string::npos ? text.size() : close + 2;
    } else if (c == '"' || c == '\'') {
      end = quotedEnd(text, i);
    } else if (isIdentifierChar(c)) {
      // A whole identifier or number, so that the ' of 1'000 is no character literal and the
      // R of R"( opens a raw string only as a prefix of its own.
      const bool number = std::isdigit(static_cast<unsigned char>(c)) != 0;
      std::size_t j = i;
      while (j < text.size() && (isIdentifierChar(text[j]) || (number && (text[j] == '\'' || text[j] == '.'))))
        ++j;
      const std::string_view word(text.data() + i, j - i);
      if (j < text.size() && text[j] == '"' && (word == "R" || word == "LR" || word == "uR" || word == "UR" || word == "u8R")) {
        const std::size_t rawEnd = rawStringEnd(text, j);
        blank(text, j, rawEnd);
        i = rawEnd;
      } else {
        i = j;
      }
      continue;
    } else {
      ++i;
      continue;
    }
    blank(text, i, end);
    i = end;
  }
  return text;
}

namespace {

enum class BlockKind { Container, Function, Data };

/// The words of `head` (identifiers and keywords) before its first parenthesis.
std::vector<std::string> leadingWords(std::string_view head) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < head.size() && head[i] != '(') {
    if (isIdentifierChar(head[i])) {
      std::size_t j = i;
      while (j < head.size() && isIdentifierChar(head[j])) ++j;
      words.emplace_back(head.substr(i, j - i));
      i = j;
    } else {
      ++i;
    }
  }
  return words;
}

/// `head` without a leading `template <...>`, whose default arguments may hold '=' and '('.
std::string_view withoutTemplatePrefix(std::string_view head) {
  const std::size_t first = head.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || head.substr(first, 8) != "template") return head;
  const std::size_t open = head.find('<', first);
  if (open == std::string_view::npos) return head;
  int depth = 0;
  for (std::size_t i = open; i < head.size(); ++i) {
    if (head[i] == '<') ++depth;
    if (head[i] == '>' && --depth == 0) return withoutTemplatePrefix(head.substr(i + 1));
  }
  return head;
}

/// Where `head` assigns (an '=' outside parentheses and brackets that is no part of an
/// operator such as ==, <=, += or operator=), or npos.
std::size_t assignment(std::string_view head) {
  int depth = 0;
  for (std::size_t i = 0; i < head.size(); ++i) {
    const char c = head[i];
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (c != '=' || depth != 0) continue;
    const char before = i > 0 ? head[i - 1] : ' ';
    const char after = i + 1 < head.size() ? head[i + 1] : ' ';
    if (after == '=' || std::string_view("=!<>+-*/%^&|").find(before) != std::string_view::npos) continue;
    const std::size_t word = head.find_last_not_of(" \t\r\n", i == 0 ? 0 : i - 1);
    if (word != std::string_view::npos && word >= 7 && head.substr(word - 7, 8) == "operator") continue;
    return i;
  }
  return std::string_view::npos;
}

/// The qualified name written just before position `end` of `head` (spaces skipped).
std::string nameBefore(std::string_view head, std::size_t end) {
  std::size_t last = head.find_last_not_of(" \t\r\n", end == 0 ? 0 : end - 1);
  if (last == std::string_view::npos) return "";
  std::size_t first = last + 1;
  while (first > 0 && (isIdentifierChar(head[first - 1]) || head[first - 1] == ':' || head[first - 1] == '~')) --first;
  if (first > last) {  // an operator's symbol, as in operator==: name it "operator"
    const std::size_t op = head.rfind("operator", end);
    return op == std::string_view::npos ? "" : std::string(head.substr(op, end - op));
  }
  return std::string(head.substr(first, last + 1 - first));
}

BlockKind classify(std::string_view fullHead, std::string& name) {
  const std::string_view head = withoutTemplatePrefix(fullHead);
  const std::vector<std::string> words = leadingWords(head);
  const auto has = [&](const char* word) { return std::find(words.begin(), words.end(), word) != words.end(); };
  const bool parenthesised = head.find('(') != std::string_view::npos;
  if (has("namespace")) return BlockKind::Container;
  if ((has("class") || has("struct") || has("union") || has("extern")) && !parenthesised) return BlockKind::Container;
  const std::size_t equals = assignment(head);
  if (equals != std::string_view::npos) {
    const std::size_t value = head.find_first_not_of(" \t\r\n", equals + 1);
    if (value == std::string_view::npos || head[value] != '[') return BlockKind::Data;
    name = nameBefore(head, equals);  // a lambda given to a variable outside any function
    return BlockKind::Function;
  }
  if (!parenthesised) return BlockKind::Data;
  name = nameBefore(head, head.find('('));
  return BlockKind::Function;
}

/// The index of the brace closing the one at `open` (or the text's last index if none does).
std::size_t matchingBrace(const std::string& text, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < text.size(); ++i) {
    if (text[i] == '{') ++depth;
    if (text[i] == '}' && --depth == 0) return i;
  }
  return text.empty() ? 0 : text.size() - 1;
}

/// The end of a declaration whose first braced block opens at `open`: a block followed by ','
/// or '{' is a member initialiser (Foo() : a_{1}, b_{2} { ... }) or one of several initialised
/// variables, and the declaration goes on to the next block.
std::size_t declarationEnd(const std::string& text, std::size_t open) {
  std::size_t close = matchingBrace(text, open);
  for (;;) {
    const std::size_t next = text.find_first_not_of(" \t\r\n", close + 1);
    if (next == std::string::npos || (text[next] != ',' && text[next] != '{')) return close;
    int parens = 0;
    std::size_t brace = next;
    while (brace < text.size() && !(text[brace] == '{' && parens == 0) && !(text[brace] == ';' && parens == 0)) {
      if (text[brace] == '(') ++parens;
      if (text[brace] == ')') --parens;
      ++brace;
    }
    if (brace >= text.size() || text[brace] != '{') return close;
    close = matchingBrace(text, brace);
  }
}

}  // namespace

std::vector<FunctionSpan> functionSpans(const std::string& source) {
  const std::string text = blankCommentsAndLiterals(source);
  std::vector<std::size_t> newlines;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') newlines.push_back(i);
  const auto lineOf = [&](std::size_t pos) {
    return static_cast<int>(std::lower_bound(newlines.begin(), newlines.end(), pos) - newlines.begin()) + 1;
  };

  std::vector<FunctionSpan> spans;
  int openContainers = 0;
  std::size_t headStart = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ';') {
      headStart = i + 1;
    } else if (c == '}') {
      if (openContainers > 0) --openContainers;
      headStart = i + 1;
    } else if (c == '{') {
      std::string name;
      const BlockKind kind = classify(std::string_view(text).substr(headStart, i - headStart), name);
      if (kind == BlockKind::Container) {
        ++openContainers;
        headStart = i + 1;
        continue;
      }
      const std::size_t end = declarationEnd(text, i);
      if (kind == BlockKind::Function) spans.push_back({name, lineOf(i), lineOf(end)});
      i = end;
      headStart = end + 1;
    }
  }
  return spans;
}

}  // namespace lathesim::structure
