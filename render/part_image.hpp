#pragma once
// The picture a user looks at first: the finished part, lit and shaded, with the toolpath.

#include <filesystem>
#include <string>

#include "geometry/triangle_mesh.hpp"
#include "interp/move.hpp"

namespace lathesim::render {

struct PartImageOptions {
  int widthPx = 1600;
  int heightPx = 1200;
  std::string title;  // drawn in a corner: the program's name
};

/// Renders off-screen to a PNG (rapids dashed red, feeds solid blue over the shaded part).
/// Works with no display: an Xvfb server is started for the process if none is reachable.
/// Throws std::runtime_error if the image cannot be made or written.
void writePartImagePng(const TriangleMesh& part, const interp::Toolpath& toolpath,
                       const PartImageOptions& options, const std::filesystem::path& png);

}  // namespace lathesim::render
