#pragma once
// Inside render only: one view of the part as a VTK scene that can be drawn again with another
// part mesh, the tool elsewhere and another caption (the animation draws it frame after frame
// in one window). writePartImagePng draws it once.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "interp/motion/toolpath_clock.hpp"
#include "render/label_layout.hpp"
#include "render/part_image.hpp"
#include "render/picture_frame.hpp"
#include "render/rgb_image.hpp"

namespace lathesim::render {

class PartPicture {
 public:
  /// `framingPart` is consulted only when options.bar is not given (the picture frames the
  /// bar when it is).
  PartPicture(const PartImageOptions& options, const interp::Toolpath& toolpath, const TriangleMesh& framingPart);
  ~PartPicture();
  PartPicture(const PartPicture&) = delete;
  PartPicture& operator=(const PartPicture&) = delete;

  const PictureFrame& frame() const;

  void setPart(const TriangleMesh& part);
  /// Marks a crash from the next show() on (the video marks one from the frame after it).
  void addCrash(const CrashMark& crash);
  /// What the overlay and the tool show: the toolpath as far as `shown` (the moves before it
  /// whole, its move up to where the tool stands; nullopt: all of it), `tool` (at
  /// shown->position when shown is given), and `caption` under the title.
  void show(const std::optional<interp::ToolpathInstant>& shown, const std::optional<ToolPicture>& tool,
            const std::string& caption);

  /// The labels as the last show() placed them, the dimension lines they keep clear of and
  /// their leaders.
  const std::vector<PlacedLabel>& labels() const;
  const std::vector<PixelSegment>& dimensionLines() const;
  const std::vector<LeaderLine>& leaders() const;  // from a moved label to what it tells about

  void writePng(const std::filesystem::path& png);
  RgbImage image();  // the picture's pixels
  /// The picture as rows of RGB bytes, top row first (as video encoders take them).
  void readRgb(std::vector<unsigned char>& rgb);

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
};

}  // namespace lathesim::render
