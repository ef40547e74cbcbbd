#pragma once
// docs/codes.md, the G- and M-code reference, written from the interpreter's own tables (the
// dialects' G codes, the common M codes, each control's machine M codes and its preset), so
// that the reference says what the interpreter reads and cannot drift from it.

#include <string>

namespace lathesim::docs {

/// The whole of docs/codes.md.
std::string codeReference();

/// How to bring docs/codes.md up to date, for messages.
inline constexpr const char* kRegenerateCodeReference = "build/tests/docs/write_code_reference docs/codes.md";

}  // namespace lathesim::docs
