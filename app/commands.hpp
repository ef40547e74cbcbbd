#pragma once
// The lathesim subcommands. Each returns the process exit status (setup/exit_status.hpp):
// 0 done, 1 bad input (diagnostics printed, no output written).

#include <filesystem>
#include <optional>
#include <vector>

#include "interp/control/dialect.hpp"
#include "interp/motion/toolpath_clock.hpp"
#include "setup/exit_status.hpp"
#include "setup/job.hpp"
#include "setup/setup.hpp"
#include "render/part_image.hpp"

namespace lathesim::app {

using setup::kDefaultVoxelMm;  // when neither --voxel nor [sim] voxel says

/// Mesh adaptivity of the exported part. Even this small value merges facets on flat and
/// gently curved faces about 40-fold (seed 000 at 0.1 mm: 12.4 M triangles → 0.30 M, a
/// 15 MB STL); larger values barely merge more but lay longer chords inside curved faces
/// (Φ50 at 0.25 mm: volume −0.05 % here, −0.17 % at 0.05).
inline constexpr double kExportAdaptivity = 0.002;

/// The pictures of the part: part.png (the isometric view) always, and these views besides.
struct PictureRequest {
  std::vector<render::PartView> views;  // --views: part-front.png, part-section.png
  int widthPx = 1600, heightPx = 1200;  // --size
  std::optional<int> thumbnailWidthPx;  // --thumbnail: thumbnail.png, a small copy of the main picture
};

/// --animate: the cut as a video, frames at an even pace.
struct AnimationRequest {
  bool mp4 = false;  // cut.mp4
  bool gif = false;  // cut.gif too
  interp::Pace pace = interp::Pace::MachineTime;
  int frames = 120;
  double framesPerSecond = 15;
  int widthPx = 800, heightPx = 600;  // --video-size
};

/// --outputs: which of the run's files are written. report.json always is; --export and
/// --animate add theirs. Names: kOutputNames.
struct OutputSelection {
  bool stl = true;   // part.stl (stub.stl after a part-off)
  bool png = true;   // the pictures: part.png, the views, thread.png; check's deviation.png, section.png
  bool vdb = true;   // stock.vdb
  bool vtp = true;   // toolpath.vtp
  bool csv = true;   // toolpath.csv
  bool html = true;  // report.html

  /// Exactly the files `names` (from kOutputNames) name, and report.json.
  static OutputSelection only(const std::vector<std::string>& names);
};
inline const std::vector<std::string> kOutputNames{"stl", "png", "vdb", "vtp", "csv", "report", "html",
                                                   "gltf", "glb", "ply", "obj", "video"};

struct RunOptions {
  std::filesystem::path program;
  std::optional<std::filesystem::path> setup;
  std::filesystem::path out = "out";
  std::optional<double> voxelMm;
  setup::SetupOverrides overrides;  // --dialect, --control, --block-skip, --max-steps
  std::optional<int> atLine;  // simulate only up to this source line (app/at_line.hpp)
  std::vector<std::filesystem::path> programDirectories;  // --programs
  std::optional<std::string> stock;  // --stock D40xL80 (setup/stock_option.hpp)
  PictureRequest pictures;
  AnimationRequest animation;
  std::vector<std::string> exports;  // --export: gltf, glb, ply, obj (part.gltf, …)
  OutputSelection outputs;           // --outputs
};

int runCommand(const RunOptions& options);

/// What `check` compares the part with: exactly one of the three.
struct CheckOptions {
  RunOptions run;
  std::optional<std::filesystem::path> drawing;        // --target: a profile (.toml) or an STL (.stl)
  std::optional<std::filesystem::path> targetProgram;  // --target-program: simulated with the same setup
  std::optional<double> toleranceMm;        // --tol: ± normal to the surface wherever the drawing states none
  std::optional<char> generalTolerance;     // --general-tolerance: ISO 2768-1 class f, m, c or v
};

/// Exit status 0 when every figure is shown within its tolerance, 3 when one is out of it or
/// undecided at the voxel, 1 on bad input (setup/exit_status.hpp).
int checkCommand(const CheckOptions& options);

/// The toolpath CSV on stdout, whole or not at all: the rows stream into an unnamed temporary
/// file as the program makes its moves (the toolpath is never held in memory) and are copied
/// to stdout once the program has run without error; exit status 1 and nothing on stdout
/// when it fails, however many moves came before the error.
int expandCommand(const setup::JobRequest& request);

/// The job a run's options name.
setup::JobRequest jobRequestOf(const RunOptions& options);

}  // namespace lathesim::app
