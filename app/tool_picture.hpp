#pragma once
// Which tool the part image shows, and where: the tool mounted for the toolpath's last move,
// standing at that move's end (or at the start position if there are no moves).

#include "job/setup.hpp"
#include "interp/base/move.hpp"
#include "render/part_image.hpp"

namespace lathesim::app {

/// Tool `number` standing at `position` (the first tool if the setup lacks it).
render::ToolPicture toolPicture(const job::Setup& setup, int number, const RZ& position);

render::ToolPicture toolPictureAtEnd(const job::Setup& setup, const interp::Toolpath& toolpath);

}  // namespace lathesim::app
