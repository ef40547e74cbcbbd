#pragma once
// Which tool the part image shows, and where: the tool mounted for the toolpath's last move,
// standing at that move's end (or at the start position if there are no moves).

#include <string>

#include "setup/setup.hpp"
#include "interp/base/move.hpp"
#include "render/part_image.hpp"

namespace lathesim::app {

/// How thick a tool is drawn across the meridian plane (part.png, the video, the 3D view).
struct DrawnToolSizes {
  double holderHeightMm = 0;    // the holder's shank height h
  double insertThicknessMm = 0;
  std::string from;             // "the holder PCLNR2525M12 and the insert's own", or the defaults taken
};
/// A named holder's shank height, else kDefaultShankHeightMm; the insert's thickness (the
/// tool's thickness key or an ISO insert's own), else sim's default insert thickness.
inline constexpr double kDefaultShankHeightMm = 25.0;  // a 2525 shank, the commonest on small lathes
DrawnToolSizes drawnToolSizes(const setup::ToolDefinition& tool);

/// Tool `number` standing at `position` (the first tool if the setup lacks it), at its size.
render::ToolPicture toolPicture(const setup::Setup& setup, int number, const RZ& position);

render::ToolPicture toolPictureAtEnd(const setup::Setup& setup, const interp::Toolpath& toolpath);

}  // namespace lathesim::app
