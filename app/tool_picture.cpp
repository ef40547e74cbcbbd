#include "app/tool_picture.hpp"

#include <algorithm>

namespace lathesim::app {

render::ToolPicture toolPictureAtEnd(const job::Setup& setup, const interp::Toolpath& toolpath) {
  render::ToolPicture picture;
  picture.position = toolpath.moves.empty() ? toolpath.startPosition : toolpath.moves.back().to;
  // The first tool is mounted at start; interp checks every T word against the setup.
  const int number = toolpath.moves.empty() ? 0 : toolpath.moves.back().tool;
  const auto tool = std::find_if(setup.tools.begin(), setup.tools.end(),
                                 [number](const job::ToolDefinition& t) { return t.number == number; });
  const job::ToolDefinition* mounted = tool != setup.tools.end() ? &*tool : setup.tools.empty() ? nullptr : &setup.tools.front();
  if (mounted == nullptr) return picture;
  picture.insert = mounted->outline.vertices();
  if (mounted->holderBody) picture.holder = mounted->holderBody->vertices();
  return picture;
}

}  // namespace lathesim::app
