// libFuzzer harness: the ISO code parsers — an insert (ISO 1832) and a holder (ISO 5608),
// the turning tool built from the two when both read, and a tool named in a program's
// comment (`CNMG 120408`, `GROOVE 3MM`, `DRILL 12`, `THREAD 60 DEG P1.5`). Errors are
// answers; a crash, a hang, a leak or undefined behaviour is a finding.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "geometry/iso_holder.hpp"
#include "geometry/iso_insert.hpp"
#include "geometry/tool_shape.hpp"
#include "setup/comment_tools.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace lathesim;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput input(data, size);
  const unsigned tip = input.choice(11);  // 10: the holder's default
  const std::string_view text = input.rest();
  const std::size_t split = text.find('|');  // "INSERT|HOLDER"
  const std::string_view insertCode = text.substr(0, split);
  const std::string_view holderCode = split == std::string_view::npos ? text : text.substr(split + 1);
  const auto insert = parseIsoInsert(insertCode);
  const auto holder = parseIsoHolder(holderCode);
  if (insert.value && holder.value)
    turningTool(*insert.value, *holder.value, tip == 10 ? std::nullopt : std::optional<int>(static_cast<int>(tip)));
  setup::toolNamedIn(std::string(text), 1, 40.0);
  return 0;
}
