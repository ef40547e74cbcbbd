// The animation's frames: at even steps of the clock, drawn before the moves they fall in are
// cut, and as many in the video as asked.

#include "render/cut_animation.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

bool ffmpegInstalled() { return std::system("ffmpeg -version >/dev/null 2>&1") == 0; }

/// Frames counted by ffprobe (Debian's ffmpeg package).
int framesIn(const std::filesystem::path& video) {
  const std::string command = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                              "-of default=nokey=1:noprint_wrappers=1 '" + video.string() + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  int frames = -1;
  if (pipe && std::fscanf(pipe.get(), "%d", &frames) != 1) frames = -1;
  return frames;
}

// Three moves of 1, 4 and 5 s: 10 s in all, so six frames fall at 0, 2, 4, 6, 8 and 10 s.
TEST(CutAnimation, FramesFallAtEvenStepsAndBeforeTheMovesTheyShow) {
  if (!ffmpegInstalled()) GTEST_SKIP() << "ffmpeg is not installed (scripts/setup.sh installs it)";
  ::unsetenv("DISPLAY");
  interp::Toolpath path = test::rapidThenFeed();
  path.moves[0].timeS = 1;
  path.moves[1].timeS = 4;
  auto third = test::move(interp::MoveKind::Feed, 29, 10, 35, 10, 5, 0.2);
  third.timeS = 5;
  path.moves.push_back(third);

  test::TempDir dir;
  AnimationOptions options;
  options.frames = 6;
  options.framesPerSecond = 6;
  options.mp4 = dir.path() / "cut.mp4";
  options.gif = dir.path() / "cut.gif";
  PartImageOptions picture;
  picture.widthPx = 320;
  picture.heightPx = 240;
  picture.bar = BarOutline{35, 0, 60};
  CutAnimation animation(picture, path, options, {}, {});
  for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(animation.clockOfFrame(k), 2.0 * k);

  int meshes = 0;
  const TriangleMesh cylinder = test::cylinder(30, 60, 24);
  const PartNow part = [&] { return ++meshes, cylinder; };
  animation.drawFramesBefore(animation.clockAtEndOf(0), part);  // the first move ends at 1 s: frame 0
  EXPECT_EQ(animation.framesDrawn(), 1);
  animation.drawFramesBefore(animation.clockAtEndOf(0), part);  // none due: the part is not asked for
  EXPECT_EQ(meshes, 1);
  animation.drawFramesBefore(animation.clockAtEndOf(1), part);  // ends at 5 s: frames at 2 and 4 s
  EXPECT_EQ(animation.framesDrawn(), 3);
  EXPECT_EQ(meshes, 2);
  animation.finish(part);  // 6, 8 and 10 s with the final part
  EXPECT_EQ(animation.framesDrawn(), 6);
  EXPECT_EQ(framesIn(dir.path() / "cut.mp4"), 6);
  EXPECT_GT(std::filesystem::file_size(dir.path() / "cut.gif"), 1000u);
}

}  // namespace
}  // namespace lathesim::render
