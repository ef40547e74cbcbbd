#include "render/cut_animation.hpp"

#include <stdexcept>

#include "render/part_picture.hpp"
#include "render/video_encoder.hpp"

namespace lathesim::render {

CutAnimation::CutAnimation(const PartImageOptions& picture, const interp::Toolpath& toolpath,
                           const AnimationOptions& options, FrameCaption caption, FrameTool tool)
    : toolpath_(toolpath), options_(options), clock_(toolpath, options.pace), caption_(std::move(caption)),
      tool_(std::move(tool)) {
  if (options_.frames < 2) throw std::invalid_argument("an animation needs at least two frames");
  picture_ = std::make_unique<PartPicture>(picture, toolpath, TriangleMesh{});
  encoder_ = std::make_unique<VideoEncoder>(picture.widthPx, picture.heightPx, options.framesPerSecond, options.mp4);
}

CutAnimation::~CutAnimation() = default;

void CutAnimation::addCrash(const CrashMark& crash) { picture_->addCrash(crash); }

double CutAnimation::stepPerFrame() const { return clock_.total() / (options_.frames - 1); }

double CutAnimation::clockOfFrame(int index) const {
  // The last frame exactly at the end, whatever the rounding of the steps before it.
  return index == options_.frames - 1 ? clock_.total() : index * stepPerFrame();
}

void CutAnimation::draw(int index, const TriangleMesh& part) {
  const double clock = clockOfFrame(index);
  const interp::ToolpathInstant instant = clock_.at(clock);
  picture_->setPart(part);
  picture_->show(instant, tool_ ? tool_(instant) : std::nullopt, caption_ ? caption_(instant, clock) : "");
  picture_->readRgb(rgb_);
  encoder_->write(rgb_);
}

void CutAnimation::drawFramesBefore(double clock, const PartNow& part) {
  if (next_ >= options_.frames || !(clockOfFrame(next_) < clock)) return;
  const TriangleMesh now = part();
  for (; next_ < options_.frames && clockOfFrame(next_) < clock; ++next_) draw(next_, now);
}

void CutAnimation::finish(const PartNow& part) {
  if (next_ < options_.frames) {
    const TriangleMesh now = part();
    for (; next_ < options_.frames; ++next_) draw(next_, now);
  }
  encoder_->finish();
  if (options_.gif) writeGifFromVideo(options_.mp4, *options_.gif, options_.gifWidthPx, options_.framesPerSecond);
}

}  // namespace lathesim::render
