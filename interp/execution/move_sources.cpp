#include "interp/execution/move_sources.hpp"

#include <algorithm>

namespace lathesim::interp {
namespace {
// Sources kept apart by their calling line, short of Toolpath::kMaxSources: the rest leave
// room for one source per file without its call (at most O1–O9999), so that a move never
// names another file than its own.
constexpr std::size_t kMaxCalledSources = Toolpath::kMaxSources - 9999;
}  // namespace

std::uint16_t MoveSources::of(int text, std::span<const std::size_t> calls) {
  if (text == 0) return 0;
  if (text == lastText_ && std::ranges::equal(calls, lastCalls_)) return last_;
  // The innermost call written in another text is the one that entered this text.
  std::uint16_t source = 0;
  bool called = false;
  for (std::size_t i = calls.size(); i-- > 0;) {
    const ProgramBlock call = program_.block(calls[i]);
    if (call.source == text) continue;
    source = entered(text, of(call.source, calls.first(i)), call.line, call.column);
    called = true;
    break;
  }
  if (!called) source = entered(text, 0, 0, 0);
  lastText_ = text, lastCalls_.assign(calls.begin(), calls.end()), last_ = source;
  return source;
}

std::uint16_t MoveSources::entered(int text, int caller, int callLine, int callColumn) {
  if (callLine != 0 && toolpath_.sources.size() >= kMaxCalledSources) return entered(text, 0, 0, 0);
  const auto [at, added] = found_.try_emplace({text, caller, callLine, callColumn}, 0);
  if (added) {
    toolpath_.sources.push_back({program_.sources[static_cast<std::size_t>(text)].name, caller, callLine, callColumn});
    at->second = static_cast<std::uint16_t>(toolpath_.sources.size());
  }
  return at->second;
}

}  // namespace lathesim::interp
