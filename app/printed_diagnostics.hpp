#pragma once
// The commands print what the libraries say: setup/ and the readers return their diagnostics,
// and these put them on standard error, in order, each in the compiler's format.

#include <iostream>
#include <utility>

#include "interp/base/diagnostic.hpp"
#include "setup/job.hpp"

namespace lathesim::app {

inline void printDiagnostics(const std::vector<interp::Diagnostic>& diagnostics) {
  for (const interp::Diagnostic& d : diagnostics) std::cerr << interp::format(d) << '\n';
}

/// A job step's result, what it said printed first.
template <class T>
T printed(setup::Reported<T> reported) {
  printDiagnostics(reported.diagnostics);
  return std::move(reported.value);
}

}  // namespace lathesim::app
