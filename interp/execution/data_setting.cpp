#include "interp/execution/data_setting.hpp"

#include <memory>
#include <string>

#include <fmt/format.h>

#include "interp/execution/work_coordinates.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {
namespace {

constexpr int kGeometryBase = 10000;  // P10000 + n: geometry entry n
constexpr int kMaxOffsetNumber = 99;  // as many as the setup's [[offset]] allows
constexpr int kWorkOffsetSystems = 6;  // G54…G59

bool isPlainInteger(const Word& word) {
  return !word.number.empty() && word.number.find_first_not_of("0123456789") == std::string::npos;
}

// One value of an entry: set by the absolute word, or changed by the incremental one.
struct ValueWords {
  std::optional<Word> absolute;
  std::optional<Word> incremental;
};

Result<ValueWords> takeValue(ParsedBlock& block, char absolute, char incremental, bool incrementalMode) {
  ValueWords words{block.take(absolute), block.take(incremental)};
  if (incrementalMode && words.absolute && !words.incremental) std::swap(words.absolute, words.incremental);
  if (words.absolute && words.incremental) {
    return Error{block.line, words.incremental->column,
                 fmt::format("{} and {} both give the same value ({} sets it, {} adds to it); give "
                             "one of them",
                             words.absolute->text(), words.incremental->text(), absolute, incremental)};
  }
  return words;
}

// `value` after the words: `scale` converts a length as read into the stored unit.
void apply(const ValueWords& words, const NumberReading& reading, double scale, double& value) {
  if (words.absolute) value = lengthMm(*words.absolute, reading) * scale;
  if (words.incremental) value += lengthMm(*words.incremental, reading) * scale;
}

Status setToolOffset(ParsedBlock& block, const Word& p, ModalState& state, const InterpreterOptions& options) {
  const int number = static_cast<int>(p.value);
  const bool geometry = number > kGeometryBase;
  const int entry = geometry ? number - kGeometryBase : number;
  if (number == 0) {
    return Error{block.line, p.column,
                 "G10 P0 sets the work coordinate system shift, which lathesim does not model; "
                 "set work offsets with G10 L2 P0…P6, or [[work_offset]] in the setup"};
  }
  if (entry < 1 || entry > kMaxOffsetNumber) {
    return Error{block.line, p.column,
                 fmt::format("{} is not a tool offset: G10 P1…P{} sets a wear entry, P{}…P{} a "
                             "geometry entry",
                             p.text(), kMaxOffsetNumber, kGeometryBase + 1, kGeometryBase + kMaxOffsetNumber)};
  }
  auto x = takeValue(block, 'X', 'U', state.incremental);
  if (!x.ok()) return x.error();
  auto z = takeValue(block, 'Z', 'W', state.incremental);
  if (!z.ok()) return z.error();
  auto r = takeValue(block, 'R', 'C', false);
  if (!r.ok()) return r.error();
  const auto q = block.take('Q');
  if (q && (!isPlainInteger(*q) || q->value > 9)) {
    return Error{block.line, q->column,
                 fmt::format("{} is not an imaginary tip number: expected Q0 to Q9", q->text())};
  }
  auto table = std::make_shared<ToolOffsets>(state.offsetTable ? *state.offsetTable : options.offsets);
  ToolOffset& o = (*table)[entry];
  const NumberReading reading = NumberReading::of(options.control, state.inch);
  apply(x.value(), reading, 1.0, geometry ? o.xDiameterMm : o.wearXDiameterMm);
  apply(z.value(), reading, 1.0, geometry ? o.zMm : o.wearZMm);
  apply(r.value(), reading, 1.0, geometry ? o.radiusMm : o.wearRadiusMm);
  if (q) o.tip = static_cast<int>(q->value);
  if (o.radiusMm + o.wearRadiusMm < 0) {
    const Word& word = r.value().absolute ? *r.value().absolute : *r.value().incremental;
    return Error{block.line, word.column,
                 fmt::format("{} leaves offset {} with a negative nose radius ({:g} mm)", word.text(),
                             entry, o.radiusMm + o.wearRadiusMm)};
  }
  state.offsetTable = std::move(table);
  return success();
}

Status setWorkOffset(ParsedBlock& block, const Word& p, ModalState& state, const InterpreterOptions& options) {
  if (!isPlainInteger(p) || p.value > kWorkOffsetSystems) {
    return Error{block.line, p.column,
                 fmt::format("{} is not a work offset: G10 L2 P0 sets the external offset, P1…P6 "
                             "those of G54…G59",
                             p.text())};
  }
  auto x = takeValue(block, 'X', 'U', state.incremental);
  if (!x.ok()) return x.error();
  auto z = takeValue(block, 'Z', 'W', state.incremental);
  if (!z.ok()) return z.error();
  WorkOffsets offsets = state.frame.offsets;
  RZ& offset = offsets[static_cast<std::size_t>(p.value)];
  const NumberReading reading = NumberReading::of(options.control, state.inch);
  apply(x.value(), reading, 0.5, offset.x());  // X is a diameter; the frame keeps radii
  apply(z.value(), reading, 1.0, offset.y());
  changeWorkOffsets(offsets, state);
  return success();
}

}  // namespace

Status applyDataSetting(ParsedBlock& block, const Code& g10, ModalState& state,
                        const InterpreterOptions& options) {
  const auto l = block.take('L');
  const auto p = block.take('P');
  if (!p) {
    return Error{block.line, g10.column,
                 "G10 needs P: P1…P99 a tool offset's wear, P10001…P10099 its geometry, or with L2 "
                 "P0…P6 a work offset"};
  }
  if (!isPlainInteger(*p)) {
    return Error{block.line, p->column,
                 fmt::format("{} is not an offset number: expected digits only", p->text())};
  }
  if (!l) return setToolOffset(block, *p, state, options);
  if (l->value != 2) {
    return Error{block.line, l->column,
                 fmt::format("G10 {}: lathesim reads G10 L2 P_ (work offsets) and G10 P_ without L "
                             "(tool offsets), the forms of Fanuc lathes",
                             l->text())};
  }
  return setWorkOffset(block, *p, state, options);
}

}  // namespace lathesim::interp
