#include "app/picture_cli.hpp"

#include <algorithm>
#include <regex>

namespace lathesim::app {
namespace {

constexpr int kLargestSidePx = 8192;

/// "1600x1200" → width and height; a message when it is not that.
std::string readSize(const std::string& text, int& width, int& height, bool even) {
  static const std::regex pattern(R"((\d{1,5})[xX×](\d{1,5}))");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return "expected WIDTHxHEIGHT in pixels, e.g. 1600x1200, not '" + text + "'";
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 64 || h < 64 || w > kLargestSidePx || h > kLargestSidePx)
    return "each side must be 64 to " + std::to_string(kLargestSidePx) + " pixels";
  if (even && (w % 2 || h % 2)) return "a video's sides must be even numbers of pixels (H.264 halves its colour planes)";
  width = w, height = h;
  return "";
}

}  // namespace

OutputSelection OutputSelection::only(const std::vector<std::string>& names) {
  const auto named = [&](const char* name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  OutputSelection selection;
  selection.stl = named("stl");
  selection.png = named("png");
  selection.vdb = named("vdb");
  selection.vtp = named("vtp");
  selection.csv = named("csv");
  selection.html = named("html");
  return selection;
}

void addPictureOptions(CLI::App& command, RunOptions& options) {
  command
      .add_option_function<std::vector<std::string>>(
          "--views",
          [&options](const std::vector<std::string>& names) {
            for (const auto& name : names) options.pictures.views.push_back(*render::viewNamed(name));
          },
          "views to draw besides part.png (iso): front → part-front.png, section → part-section.png")
      ->delimiter(',')
      ->check(CLI::IsMember({"iso", "front", "section"}));
  command
      .add_option_function<std::string>(
          "--size",
          [&options](const std::string& text) {
            if (auto problem = readSize(text, options.pictures.widthPx, options.pictures.heightPx, false); !problem.empty())
              throw CLI::ValidationError("--size", problem);
          },
          "the pictures' size in pixels (default 1600x1200)");
  command.add_option("--thumbnail", options.pictures.thumbnailWidthPx,
                     "also thumbnail.png, about this many pixels wide: part.png (check: deviation.png) shrunk")
      ->check(CLI::Range(16, kLargestSidePx));
  command.add_option("--export", options.exports, "more files of the part: gltf, glb, ply, obj (part.gltf, …)")
      ->delimiter(',')
      ->check(CLI::IsMember({"gltf", "glb", "ply", "obj"}));
  command
      .add_option_function<std::vector<std::string>>(
          "--outputs",
          [&options](const std::vector<std::string>& names) {
            options.outputs = OutputSelection::only(names);
            for (const auto& name : names) {
              const bool export_ = name == "gltf" || name == "glb" || name == "ply" || name == "obj";
              if (export_ && std::find(options.exports.begin(), options.exports.end(), name) == options.exports.end())
                options.exports.push_back(name);
              if (name == "video") options.animation.mp4 = true;
            }
          },
          "write only these (report.json always): stl, png, vdb, vtp, csv, report, html, and gltf, glb, ply, obj, "
          "video as --export and --animate would")
      ->delimiter(',')
      ->check(CLI::IsMember(kOutputNames));
  auto* animate = command.add_flag("--animate", options.animation.mp4, "write the cut as a video, cut.mp4 (needs ffmpeg)");
  command.add_flag("--gif", options.animation.gif, "with --animate: cut.gif too")->needs(animate);
  command
      .add_option_function<std::string>(
          "--pace", [&options](const std::string& pace) {
            options.animation.pace = pace == "travel" ? interp::Pace::Travel : interp::Pace::MachineTime;
          },
          "frames at even steps of machine time (time, the default) or of tool travel (travel)")
      ->check(CLI::IsMember({"time", "travel"}))
      ->needs(animate);
  command.add_option("--frames", options.animation.frames, "how many frames (default 120, at 15 per second)")
      ->check(CLI::Range(2, 100000))
      ->needs(animate);
  command
      .add_option_function<std::string>(
          "--video-size",
          [&options](const std::string& text) {
            if (auto problem = readSize(text, options.animation.widthPx, options.animation.heightPx, true); !problem.empty())
              throw CLI::ValidationError("--video-size", problem);
          },
          "the video's size in pixels (default 800x600)")
      ->needs(animate);
}

}  // namespace lathesim::app
