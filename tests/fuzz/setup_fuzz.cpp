// libFuzzer harness: a setup file (TOML) read and checked — stock, machine, control, tools by
// polygon, ISO code or kind, offsets, work offsets, chuck. Errors are answers; a crash, a
// hang, a leak or undefined behaviour is a finding.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "setup/setup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const lathesim::setup::SetupResult result = lathesim::setup::parseSetup(text, "setup.toml");
  for (const auto& d : result.diagnostics) lathesim::interp::format(d);
  if (result.setup) lathesim::setup::travelOf(*result.setup);
  return 0;
}
