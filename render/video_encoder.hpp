#pragma once
// ffmpeg (Debian's) as a child process: raw RGB frames in on its standard input, an H.264
// MP4 out; and an MP4 turned into a GIF.

#include <filesystem>
#include <string>
#include <vector>

#include <sys/types.h>

namespace lathesim::render {

class VideoEncoder {
 public:
  /// Starts `ffmpeg` encoding widthPx × heightPx frames at `framesPerSecond` into `mp4`.
  /// Throws std::runtime_error (saying to install the ffmpeg package) if it cannot start.
  VideoEncoder(int widthPx, int heightPx, double framesPerSecond, const std::filesystem::path& mp4);
  ~VideoEncoder();  // an encoder not finished is stopped (the file it wrote is left to the caller)
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  /// One frame: heightPx rows of widthPx RGB byte triples, top row first.
  void write(const std::vector<unsigned char>& rgb);
  /// Ends the video and waits for ffmpeg; throws with ffmpeg's message if it failed.
  void finish();

 private:
  pid_t pid_ = -1;
  int input_ = -1;
  std::filesystem::path log_;
  std::size_t frameBytes_;
};

/// Converts `mp4` into an animated GIF `widthPx` wide at `framesPerSecond`, on a palette made
/// from its frames. Throws std::runtime_error with ffmpeg's message on failure.
void writeGifFromVideo(const std::filesystem::path& mp4, const std::filesystem::path& gif, int widthPx,
                       double framesPerSecond);

}  // namespace lathesim::render
