#pragma once
// The picture a user looks at first: the finished part, lit and shaded, with the toolpath.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "interp/move.hpp"

namespace lathesim::render {

/// A tool as drawn: plain outlines in [radial, axial] mm from the programmed point, and
/// where that point stands (radius mm, Z mm).
struct ToolPicture {
  std::vector<RZ> insert;  // the cutter; drawn gold
  std::vector<RZ> holder;  // the holder body; may be empty (polygon-only tools); drawn steel grey
  RZ position{0, 0};
};

/// A part of the picture to frame instead of the whole: the box Z `zLowMm`…`zHighMm` ×
/// radius `radiusLowMm`…`radiusHighMm` of the meridian plane facing the viewer's up (a
/// thread's close-up: its profile on the silhouette, its grooves on the face below).
struct CloseUp {
  double zLowMm = 0, zHighMm = 0;
  double radiusLowMm = 0, radiusHighMm = 0;
};

struct PartImageOptions {
  int widthPx = 1600;
  int heightPx = 1200;
  std::string title;  // drawn in a corner: the program's name
  std::optional<ToolPicture> tool{};  // drawn where it stands, if given
  std::optional<CloseUp> closeUp{};   // frame this box only, without the toolpath and the tool
};

/// Renders off-screen to a PNG (rapids dashed red, feeds solid blue, thread moves solid green
/// over the shaded part, and the tool, if given, as gold insert and grey holder slabs in the
/// meridian plane).
/// Works with no display: an Xvfb server is started for the process if none is reachable.
/// Throws std::runtime_error if the image cannot be made or written.
void writePartImagePng(const TriangleMesh& part, const interp::Toolpath& toolpath,
                       const PartImageOptions& options, const std::filesystem::path& png);

}  // namespace lathesim::render
