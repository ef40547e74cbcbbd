#pragma once
// What the part pictures of a run show: the bar as the setup gives it, the chuck as it places
// it, the tool at the end, and the main dimensions measured on the part's section.

#include <optional>
#include <string>
#include <vector>

#include "geometry/meridian_profile.hpp"
#include "setup/setup.hpp"
#include "render/part_image.hpp"
#include "render/scene_export.hpp"

namespace lathesim::app {

/// What every picture of the run shows whatever the part (the view left at Iso): the title,
/// the bar, the chuck, the tool at the end; widthPx × heightPx.
render::PartImageOptions partPictureOptions(const setup::Setup& setup, const interp::Toolpath& toolpath,
                                            const std::string& title, int widthPx, int heightPx);

/// The machine report.html's 3D view shows beside the part: as partPictureOptions draws it.
render::SceneMachine sceneMachine(const setup::Setup& setup, const interp::Toolpath& toolpath);

/// The pictures' title: the program, and ", at line N" for --at-line.
std::string pictureTitle(const std::string& program, std::optional<int> atLine);

/// The line under it: the bar, each tool of `toolsUsed` (numbers) as the setup describes it,
/// and the cycle time: "bar Ø40 × 60, bore Ø10 · T01 CNMG120408, T03 a blade 3 mm wide · cycle
/// time 0:12.3".
std::string pictureSubtitle(const setup::Setup& setup, const std::vector<int>& toolsUsed, double cycleTimeS);

/// The tools `moves` use, in the order of first use.
std::vector<int> toolsUsedBy(const std::vector<interp::Move>& moves);

/// How far the toolpath drawn in pictures of widthPx × heightPx may stray from the true one
/// (render/drawn_toolpath.hpp), mm: a fifth of a pixel at the scale that frames the bar, which
/// is the largest scale a picture of the run takes (it frames the bar with a margin).
double drawnToleranceMm(const setup::Setup& setup, int widthPx, int heightPx);

/// Adds what the finished part's `section` (sampled at `voxelMm`) shows: its main dimensions
/// and its cut face.
void addPartSection(render::PartImageOptions& options, const SampledSection& section, double voxelMm);

}  // namespace lathesim::app
