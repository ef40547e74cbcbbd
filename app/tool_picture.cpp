#include "app/tool_picture.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "sim/simulate.hpp"

namespace lathesim::app {

DrawnToolSizes drawnToolSizes(const setup::ToolDefinition& tool) {
  DrawnToolSizes sizes;
  const setup::ToolFacts& facts = tool.facts;
  sizes.holderHeightMm = facts.shankHeightMm.value_or(kDefaultShankHeightMm);
  sizes.insertThicknessMm = tool.thicknessMm.value_or(sim::kDefaultInsertThicknessMm);
  sizes.from = facts.shankHeightMm ? "the holder " + facts.holder + "'s shank height"
                                   : fmt::format("no holder named: a {:g} mm shank assumed", kDefaultShankHeightMm);
  sizes.from += tool.thicknessMm ? std::string(", the insert's own thickness")
                                 : fmt::format(", the insert {:g} mm thick, assumed", sim::kDefaultInsertThicknessMm);
  return sizes;
}

render::ToolPicture toolPicture(const setup::Setup& setup, int number, const RZ& position) {
  render::ToolPicture picture;
  picture.position = position;
  const auto tool = std::find_if(setup.tools.begin(), setup.tools.end(),
                                 [number](const setup::ToolDefinition& t) { return t.number == number; });
  const setup::ToolDefinition* mounted = tool != setup.tools.end() ? &*tool : setup.tools.empty() ? nullptr : &setup.tools.front();
  if (mounted == nullptr) return picture;
  picture.insert = mounted->outline.vertices();
  if (mounted->holderBody) picture.holder = mounted->holderBody->vertices();
  const DrawnToolSizes sizes = drawnToolSizes(*mounted);
  picture.holderHeightMm = sizes.holderHeightMm;
  picture.insertThicknessMm = sizes.insertThicknessMm;
  return picture;
}

render::ToolPicture toolPictureAtEnd(const setup::Setup& setup, const interp::Toolpath& toolpath) {
  // The first tool is mounted at start; interp checks every T word against the setup.
  if (toolpath.moves.empty()) return toolPicture(setup, 0, toolpath.startPosition);
  const interp::Move& last = toolpath.moves.back();
  render::ToolPicture picture = toolPicture(setup, last.tool, last.to);
  picture.programShift = last.workShift + last.offsetShift;
  return picture;
}

}  // namespace lathesim::app
