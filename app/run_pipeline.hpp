#pragma once
// The steps `run` and `check` share: load and simulate a program, mesh the part, and stage
// the run's output files (part.stl, toolpath.csv, toolpath.vtp, stock.vdb, part.png).

#include <chrono>
#include <future>
#include <memory>
#include <optional>

#include "app/commands.hpp"
#include "setup/job.hpp"
#include "app/progress.hpp"
#include "app/report.hpp"
#include "app/report_html.hpp"
#include "app/staged_output.hpp"
#include "app/step_recording.hpp"
#include "geometry/triangle_mesh.hpp"
#include "interp/output/move_spool.hpp"
#include "interp/output/toolpath_csv_spool.hpp"
#include "render/drawn_toolpath.hpp"
#include "render/rgb_image.hpp"
#include "sim/block_rows.hpp"
#include "sim/stock.hpp"

namespace lathesim::app {

class Stopwatch {
 public:
  /// Seconds since the last lap (or the start).
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }
  /// Seconds since the start.
  double total() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_ = start_;
};

struct SimulatedRun {
  setup::Job job;
  std::unique_ptr<sim::Stock> stock;  // after a part-off, the stub left in the chuck
  std::unique_ptr<Progress> progress;
  RunFigures figures;  // parse and simulate filled; mesh and render by the later steps
  TriangleMesh part;   // empty until meshPart
  TriangleMesh stub;   // after a part-off: the stub's mesh (meshPart)
  std::vector<HtmlPicture> pictures;  // staged, for report.html
  std::string modelGlb;               // the part and toolpath for report.html's 3D view
  render::RgbImage partPixels;        // part.png's, kept for thumbnail.png when --thumbnail asks
  OutputSelection outputs;            // the files to write (--outputs)
  // toolpath.csv's rows, spooled as a streamed run's moves passed (job.toolpath has no moves
  // then); null when the moves were kept, or no CSV is asked for.
  std::unique_ptr<interp::ToolpathCsvSpool> csv;
  // A streamed run's report rows (figures.simulation.blocks is empty then); null otherwise.
  std::unique_ptr<sim::SpooledBlockRows> blockRows;
  // Every move, spooled, when something reads them all after the simulation (toolpath.vtp,
  // check's gouge causes and process figures); null otherwise.
  std::unique_ptr<interp::MoveSpool> moves;
  // The toolpath as the pictures and the 3D view draw it, when they are asked for; null otherwise.
  std::unique_ptr<render::DrawnToolpath> drawn;
  // The run block by block for report.html's stepping; null when no report.html is written.
  std::unique_ptr<StepRecording> steps;
  bool video = false;  // cut.mp4 was recorded: report.html shows it

  bool partedOff() const { return figures.simulation.part != nullptr; }
  /// The finished part: the piece that parted off, or else the stock.
  const sim::Stock& partStock() const { return partedOff() ? *figures.simulation.part : *stock; }
};

sim::ToolOutlines outlinesOf(const setup::Setup& setup);
sim::ToolThicknesses thicknessesOf(const setup::Setup& setup);

/// Reads the setup and program, checks the grid and simulates (progress on a terminal);
/// records the cut into `out` when options.animation asks and `out` is given. The moves are
/// kept in run.job.toolpath when --animate or --at-line asks; otherwise they stream from the
/// interpreter into the simulation (and toolpath.csv's spool), and nothing is held for each
/// (what is held for each block: its report row, sim::BlockRemoval). Either way they are
/// spooled into run.moves when toolpath.vtp is asked for or `spoolMoves` says, and drawn into
/// run.drawn when a picture, report.html or glTF/GLB is.
/// Bad input: the diagnostics are printed and nullopt returned.
std::optional<SimulatedRun> simulateProgram(const RunOptions& options, Stopwatch& clock, StagedOutput* out,
                                            bool spoolMoves = false);

/// The run's report rows, wherever they are (spooled, or in figures.simulation.blocks), to `use`.
void useBlockRows(const SimulatedRun& run, const std::function<void(const sim::BlockRows&)>& use);

/// Meshes the part into run.part, and after a part-off the stub into run.stub (figures: mesh
/// volumes, triangles, time).
void meshPart(SimulatedRun& run, Stopwatch& clock);

/// Stages stock.vdb in a thread of its own, while the part is meshed: finishStockFile before
/// staging the other files.
std::future<double> stageStockFile(const SimulatedRun& run, StagedOutput& out);
/// Waits for stock.vdb (rethrowing a failure), adds its time to the writing, and notes the
/// stock's memory again: writing it may have built the level set (noteStockMemory).
void finishStockFile(SimulatedRun& run, std::future<double>& stockFile);
/// Raises figures.gridMemoryMb to what the stock (and the part taken from it) hold now.
void noteStockMemory(SimulatedRun& run);

/// Stages the run's other files into `out` (the pictures as options.pictures asks, the exports;
/// stub.stl too after a part-off): the pictures are drawn (timing.renderS) while the files are
/// written (timing.writeS), and returns once every file staged so far is on the disk.
void stageRunFiles(SimulatedRun& run, const RunOptions& options, StagedOutput& out, Stopwatch& clock);

/// Stages thumbnail.png, `picture` (part.png's or deviation.png's pixels) shrunk, when
/// options.pictures asks for it and there is a picture.
void stageThumbnail(const RunOptions& options, const render::RgbImage& picture, StagedOutput& out);

/// Stages report.json (`report`) and report.html.
void stageReports(const SimulatedRun& run, const nlohmann::ordered_json& report, StagedOutput& out);

/// This process's peak resident memory so far (MB; an Xvfb it started is not counted).
double peakMemoryMb();

/// Keeps `run` until the process ends, unfreed: a command's process ends right after it, and
/// its memory goes back to the system at once then, rather than block by block (seed 000's
/// grid, table and meshes: 42–46 ms of a batch job's tail). Kept reachable, so that leak
/// checkers see nothing lost. Once per process.
void keepUntilExit(SimulatedRun run);

}  // namespace lathesim::app
