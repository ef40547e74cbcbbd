#pragma once
// Setup files given as text, read as a file named part.toml, and the diagnostics a test
// expects of a file that must fail.

#include <gtest/gtest.h>

#include <string_view>

#include "setup/setup.hpp"

namespace lathesim::setup::test {

inline SetupResult parse(std::string_view text) { return parseSetup(text, "part.toml"); }

/// The one diagnostic of a file that should fail with it alone (no warning beside it).
inline interp::Diagnostic onlyDiagnostic(std::string_view text) {
  const SetupResult result = parse(text);
  EXPECT_FALSE(result.setup.has_value());
  EXPECT_EQ(result.diagnostics.size(), 1u);
  if (result.diagnostics.empty()) return {};
  return result.diagnostics.front();
}

/// The one error of a file that should fail with exactly one (warnings may come with it).
inline interp::Diagnostic onlyError(std::string_view text) {
  const SetupResult result = parse(text);
  EXPECT_FALSE(result.setup.has_value());
  int errors = 0;
  interp::Diagnostic first;
  for (const auto& d : result.diagnostics)
    if (d.severity == interp::Severity::Error && errors++ == 0) first = d;
  EXPECT_EQ(errors, 1);
  return first;
}

}  // namespace lathesim::setup::test
