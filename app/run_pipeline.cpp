#include "app/run_pipeline.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <iostream>

#include "app/at_line.hpp"
#include "app/collision_diagnostics.hpp"
#include "app/cut_recording.hpp"
#include "app/output_names.hpp"
#include "app/part_pictures.hpp"
#include "app/printed_diagnostics.hpp"
#include "app/tool_table.hpp"
#include "setup/collision_checks.hpp"
#include "measure/volume_checks.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/base/printable_text.hpp"
#include "interp/output/toolpath_csv.hpp"
#include "interp/output/toolpath_csv_spool.hpp"
#include "measure/thread_moves.hpp"
#include "measure/thread_measure.hpp"
#include "render/close_up_region.hpp"
#include "render/mesh_files.hpp"
#include "render/toolpath_vtp.hpp"
#include "render/offscreen_display.hpp"
#include "render/part_image.hpp"
#include "render/scene_export.hpp"
#include "render/thumbnail.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

namespace {

// A warning for the report, also printed on stderr; line 0 when it concerns the whole run.
void warn(SimulatedRun& run, int line, int column, const std::string& message, int source = 0) {
  run.figures.warnings.push_back(run.job.warningAt(line, column, message, source));
  std::cerr << interp::format(run.figures.warnings.back()) << '\n';
}
void warn(SimulatedRun& run, const std::string& message) { warn(run, 0, 0, message); }

}  // namespace

sim::ToolOutlines outlinesOf(const setup::Setup& setup) {
  sim::ToolOutlines tools;
  for (const auto& tool : setup.tools) tools.emplace(tool.number, tool.outline);
  return tools;
}

sim::ToolThicknesses thicknessesOf(const setup::Setup& setup) {
  sim::ToolThicknesses thicknesses;
  for (const auto& tool : setup.tools)
    if (tool.thicknessMm) thicknesses.emplace(tool.number, *tool.thicknessMm);
  return thicknesses;
}

namespace {

// Whether `options` need every move in memory: --animate draws the toolpath as far as each
// frame's instant, and --at-line cuts the toolpath at a line before it is simulated. Every
// other output reads the moves as they stream, or a spool or drawing of them after.
bool keepsMoves(const RunOptions& options) { return options.animation.mp4 || options.atLine.has_value(); }

bool drawsToolpath(const RunOptions& options) {
  const auto exported = [&](const char* format) {
    return std::find(options.exports.begin(), options.exports.end(), format) != options.exports.end();
  };
  return options.outputs.png || options.outputs.html || exported("gltf") || exported("glb");
}

// A streamed run's moves, each handed on as the interpreter makes it: to the simulation, to
// `others` (toolpath.csv's spool, the move spool, the drawing, those asked for), and to the
// moves kept for measuring threads; counted, and their machine time summed in program order
// (as cycleTimeS sums them).
class StreamedMoves final : public interp::MoveSink {
 public:
  StreamedMoves(sim::Simulation& simulation, std::vector<interp::MoveSink*> others, std::vector<interp::Move>& threadMoves,
                ToolUsage& tools)
      : simulation_(simulation), others_(std::move(others)), threads_(threadMoves), tools_(tools) {}
  void recordingIn(const interp::Toolpath& toolpath) override { simulation_.recordingIn(toolpath); }
  void take(interp::Move move) override {
    ++count;
    cycleTimeS += move.timeS;
    tools_.note(move);
    for (interp::MoveSink* other : others_) other->take(move);
    threads_.take(move);
    simulation_.take(std::move(move));
  }

  std::size_t count = 0;
  double cycleTimeS = 0;

 private:
  sim::Simulation& simulation_;
  std::vector<interp::MoveSink*> others_;
  measure::ThreadMoveCollector threads_;
  ToolUsage& tools_;
};

}  // namespace

std::optional<SimulatedRun> simulateProgram(const RunOptions& options, Stopwatch& clock, StagedOutput* out,
                                            bool spoolMoves) {
  const setup::JobRequest request = jobRequestOf(options);
  std::optional<setup::Job> opened = printed(setup::openJob(request));
  if (!opened) return std::nullopt;
  const double voxel = options.voxelMm.value_or(opened->setup.voxelMm.value_or(kDefaultVoxelMm));
  const auto gridProblem = sim::gridProblem(opened->setup.stock, voxel);
  // A bad grid is said after the program's errors (and --at-line's): the program runs first.
  const bool streams = !keepsMoves(options) && !gridProblem;
  if (!streams) {
    std::vector<interp::Move> moves;
    interp::MoveCollector collect(moves);
    if (!printed(setup::interpretJob(*opened, request, collect))) return std::nullopt;
    opened->toolpath.moves = std::move(moves);
    if (!cutAtLine(options.atLine, *opened)) return std::nullopt;
  }
  if (gridProblem) {
    std::cerr << "lathesim: error: " << *gridProblem << '\n';
    return std::nullopt;
  }
  SimulatedRun run;
  run.job = std::move(*opened);
  RunFigures& figures = run.figures;
  figures.atLine = options.atLine;
  figures.timing.parseS = clock.lap();

  const setup::Setup& setup = run.job.setup;
  figures.program = options.program.string();
  figures.setup = setup.sourceName;
  figures.control = setup.control;
  figures.machine = run.job.machine;
  figures.travel = setup::travelOf(setup);
  figures.assumed = setup::machineAssumptions(setup);
  figures.voxelMm = voxel;
  if (out && !out->foreignFiles().empty()) {
    std::string names;
    for (const std::string& name : out->foreignFiles()) names += (names.empty() ? "" : ", ") + interp::printable(name);
    warn(run, interp::printable(options.out.string()) + " holds files lathesim does not write, left as they are: " +
                  names + " (the outputs an earlier run left there and this one does not write are removed)");
  }

  run.outputs = options.outputs;
  if (options.outputs.vtp || spoolMoves) run.moves = std::make_unique<interp::MoveSpool>();
  if (drawsToolpath(options))
    run.drawn = std::make_unique<render::DrawnToolpath>(
        drawnToleranceMm(setup, options.pictures.widthPx, options.pictures.heightPx));
  if (options.outputs.html && out) run.steps = std::make_unique<StepRecording>(voxel);
  // The sinks besides the simulation that every move goes to, whether streamed or kept.
  std::vector<interp::MoveSink*> others;
  for (interp::MoveSink* sink : {static_cast<interp::MoveSink*>(run.moves.get()), static_cast<interp::MoveSink*>(run.drawn.get()),
                                 static_cast<interp::MoveSink*>(run.steps.get())})
    if (sink) others.push_back(sink);
  run.progress = std::make_unique<Progress>(figures.program);
  Stopwatch bar;
  run.stock = std::make_unique<sim::Stock>(setup.stock, voxel);
  figures.timing.barS = bar.lap();
  noteStockMemory(run);
  figures.stockVolumeMm3 = run.stock->volumeMm3();
  const auto barProblem = measure::barVolumeProblem(setup.stock, figures.stockVolumeMm3, voxel);
  const sim::CollisionChecks checks = setup::collisionChecksOf(setup);  // holders and the chuck
  const sim::ToolOutlines outlines = outlinesOf(setup);
  const sim::BlockProgress progress = [&](int done, int total) { run.progress->update(done, total); };
  std::unique_ptr<CutRecording> recording;
  if (options.animation.mp4 && out)
    recording =
        std::make_unique<CutRecording>(run.job, options.animation, pictureTitle(figures.program, options.atLine), *out);
  // What the simulation shows the stock to as it cuts: the video's frames, the page's steps.
  std::vector<sim::CutObserver> observers;
  if (recording) observers.push_back(recording->observer());
  if (run.steps) observers.push_back(run.steps->observer());
  const sim::CutObserver observer =
      observers.empty() ? sim::CutObserver{}
                        : [observers](std::size_t first, std::size_t end, const sim::Stock& stock,
                                      const std::vector<sim::Collision>& collisions) {
                            for (const auto& each : observers) each(first, end, stock, collisions);
                          };
  // A streamed run's toolpath for measuring threads: its thread moves (thread_moves.hpp).
  interp::Toolpath threadToolpath;
  ToolUsage toolUsage;
  if (streams) {
    sim::Simulation simulation(run.job.toolpath, outlines, *run.stock, {progress, &checks, thicknessesOf(setup), observer});
    if (options.outputs.csv && out) {
      run.csv = std::make_unique<interp::ToolpathCsvSpool>();
      others.push_back(run.csv.get());
    }
    std::vector<interp::Move> threadMoves;
    run.blockRows = std::make_unique<sim::SpooledBlockRows>();
    simulation.sendBlocksTo([rows = run.blockRows.get()](const sim::BlockRemoval& row) { rows->add(row); });
    StreamedMoves moves(simulation, std::move(others), threadMoves, toolUsage);
    if (!printed(setup::interpretJob(run.job, request, moves))) return std::nullopt;
    figures.moves = moves.count;
    figures.cycleTimeS = moves.cycleTimeS;
    if (barProblem) warn(run, *barProblem);  // after the program's warnings, as when it ran first
    figures.simulation = simulation.finish(run.job.toolpath);
    threadToolpath = run.job.toolpath;
    threadToolpath.moves = std::move(threadMoves);
  } else {
    for (interp::MoveSink* other : others)
      for (const interp::Move& move : run.job.toolpath.moves) other->take(move);
    for (const interp::Move& move : run.job.toolpath.moves) toolUsage.note(move);
    figures.moves = run.job.toolpath.moves.size();
    figures.cycleTimeS = interp::cycleTimeS(run.job.toolpath);
    if (barProblem) warn(run, *barProblem);
    figures.simulation =
        sim::simulate(run.job.toolpath, outlines, *run.stock, {progress, &checks, thicknessesOf(setup), observer});
  }
  figures.warnings.insert(figures.warnings.begin(), run.job.warnings.begin(), run.job.warnings.end());
  figures.tools = toolTableJson(setup, toolUsage.used());
  for (const UsedToolOffset& u : toolUsage.used())
    if (std::find(figures.toolsUsed.begin(), figures.toolsUsed.end(), u.tool) == figures.toolsUsed.end())
      figures.toolsUsed.push_back(u.tool);
  figures.stock = stockJson(setup);
  figures.notes = run.job.notes;
  figures.stops = run.job.toolpath.stops;
  figures.skipped = run.job.skippedBlocks;
  if (run.steps) {
    run.steps->finish(*run.stock);
    figures.timing.stepsS = run.steps->secondsSpent();
  }
  run.video = recording != nullptr;
  if (recording) {
    run.progress->stage("finishing the video");
    recording->finish(*run.stock, figures.simulation.collisions);
    figures.timing.animateS = recording->secondsSpent();
  }
  figures.finalVolumeMm3 = run.stock->volumeMm3();
  noteStockMemory(run);
  if (run.partedOff()) {  // what is left is the stub and the pieces that fell
    figures.stubVolumeMm3 = figures.finalVolumeMm3;
    for (const auto& off : figures.simulation.partOffs) figures.finalVolumeMm3 += off.volumeMm3;
  }
  // A thread is measured on the part: after a part-off, on the piece that fell.
  figures.threads =
      measure::measureThreads(run.partStock(), streams ? threadToolpath : run.job.toolpath, outlines, setup.dialect);
  figures.timing.simulateS = clock.lap() - figures.timing.animateS - figures.timing.stepsS;
  for (const auto& w : figures.simulation.warnings) warn(run, w.line, w.column, w.message, w.source);
  for (const auto& collision : figures.simulation.collisions) {
    figures.collisions.push_back(collisionDiagnostic(run.job, collision));
    std::cerr << interp::format(figures.collisions.back()) << '\n';
  }
  for (const auto& thread : figures.threads)
    if (const auto tooWide = measure::threadToolTooWide(thread, outlines.at(thread.programmed.tool), voxel))
      warn(run, thread.programmed.line, thread.programmed.column, *tooWide);
  return run;
}

void meshPart(SimulatedRun& run, Stopwatch& clock) {
  run.progress->stage("meshing");
  RunFigures& figures = run.figures;
  // After a part-off the stub is meshed and checked beside the part: each mesh keeps both
  // cores busy only part of the time (the welding and the checks are serial).
  std::future<measure::MeshCheck> stubCheck;
  if (run.partedOff())
    stubCheck = std::async(std::launch::async, [&run, &figures] {
      run.stub = run.stock->mesh(kExportAdaptivity);
      return measure::checkMesh(run.stub, figures.stubVolumeMm3, figures.voxelMm, "stub");
    });
  run.part = run.partStock().mesh(kExportAdaptivity);
  // The level set's volume is checked against the whole mesh; crumbs thinner than a voxel
  // are then left out of the STL, and what they held is reported.
  const double partMm3 = run.partedOff() ? figures.simulation.partOffs.front().volumeMm3 : figures.finalVolumeMm3;
  const measure::MeshCheck part = measure::checkMesh(run.part, partMm3, figures.voxelMm);
  if (part.volumeProblem) warn(run, *part.volumeProblem);
  figures.meshCrumbs = part.crumbs;
  if (part.closureProblem) warn(run, *part.closureProblem);
  if (stubCheck.valid()) {  // its warnings after the part's, as when it was meshed after it
    const measure::MeshCheck stub = stubCheck.get();
    if (stub.volumeProblem) warn(run, *stub.volumeProblem);
    if (stub.closureProblem) warn(run, *stub.closureProblem);
    figures.stubMeshVolumeMm3 = stub.volumeMm3;
  }
  figures.meshVolumeMm3 = part.volumeMm3;
  figures.volumeToleranceMm3 = sim::volumeToleranceMm3(part.areaMm2, figures.voxelMm);
  figures.meshTriangles = run.part.triangles.size();
  figures.timing.meshS = clock.lap();
}

void noteStockMemory(SimulatedRun& run) {
  constexpr double kMb = 1024.0 * 1024.0;
  const std::uint64_t bytes = run.stock->memoryBytes() + (run.partedOff() ? run.partStock().memoryBytes() : 0);
  run.figures.gridMemoryMb = std::max(run.figures.gridMemoryMb, static_cast<double>(bytes) / kMb);
}

void finishStockFile(SimulatedRun& run, std::future<double>& stockFile) {
  run.figures.timing.writeS += stockFile.get();
  noteStockMemory(run);  // writing it may have built the level set
}

std::future<double> stageStockFile(const SimulatedRun& run, StagedOutput& out) {
  if (!run.outputs.vdb) return std::async(std::launch::deferred, [] { return 0.0; });
  return std::async(std::launch::async, [&run, &out] {
    Stopwatch writing;
    out.write("stock.vdb", [&](const std::filesystem::path& file) {
      run.stock->writeVdb(file, run.figures.simulation.part.get());
    });
    return writing.lap();
  });
}

namespace {

struct DrawnPicture {
  std::string file;         // its name in the output folder
  std::string description;  // for report.html
  std::string png;          // the encoded picture
};

struct DrawnPictures {
  std::vector<DrawnPicture> files;
  render::RgbImage partPixels;  // part.png's, when a thumbnail is asked
};

// part.png, the views asked for, and a thread's close-up, drawn into memory.
DrawnPictures drawPictures(const SimulatedRun& run, const interp::Toolpath& toolpath, const RunOptions& options) {
  DrawnPictures drawn;
  const PictureRequest& pictures = options.pictures;
  render::PartImageOptions image =
      partPictureOptions(run.job.setup, toolpath, pictureTitle(run.figures.program, run.figures.atLine), pictures.widthPx,
                         pictures.heightPx);
  image.subtitle = pictureSubtitle(run.job.setup, run.figures.toolsUsed, run.figures.cycleTimeS);
  addPartSection(image, run.partStock().meridianSection(), run.figures.voxelMm);
  image.crashes = crashMarksOf(run.figures.simulation.collisions);
  std::vector<render::PartView> views{render::PartView::Iso};
  for (const render::PartView view : pictures.views)
    if (std::find(views.begin(), views.end(), view) == views.end()) views.push_back(view);
  for (const render::PartView view : views) {
    image.view = view;
    render::RgbImage pixels = render::partImage(run.part, toolpath, image);
    drawn.files.push_back({pictureFileName(view), pictureFileName(view) + ": the " + std::string(render::viewName(view)) + " view",
                           render::encodePng(pixels)});
    if (view == render::PartView::Iso && pictures.thumbnailWidthPx) drawn.partPixels = std::move(pixels);
  }
  // A close-up of the first thread measured: six pitches around the middle of its grooves,
  // from a pitch inside its root to half a pitch outside its crest, seen from the front so
  // that its profile shows true on the silhouette.
  for (const auto& thread : run.figures.threads) {
    if (thread.measured.problem) continue;
    const measure::ThreadMeasurement& m = thread.measured;
    const double middle = 0.5 * (m.zLowMm + m.zHighMm), pitch = m.pitchMm.mean;
    const double inner = 0.5 * std::min(m.minorDiameterMm.min, m.majorDiameterMm.min);
    const double outer = 0.5 * std::max(m.majorDiameterMm.max, m.minorDiameterMm.max);
    render::PartImageOptions closeUp;
    closeUp.widthPx = pictures.widthPx;
    closeUp.heightPx = pictures.heightPx;
    closeUp.view = render::PartView::Front;
    closeUp.title = run.figures.program + ", thread of line " + std::to_string(thread.programmed.line);
    const render::CloseUp box{middle - 3 * pitch, middle + 3 * pitch, inner - 2 * pitch, outer + pitch};
    closeUp.closeUp = box;
    // Its own mesh, of what the picture shows only, finer than the voxels.
    const render::CloseUpRegion region = render::closeUpRegion(box, pictures.widthPx, pictures.heightPx, run.figures.voxelMm);
    const TriangleMesh closeUpMesh = run.partStock().mesh(region.low, region.high, region.subdivisions);
    drawn.files.push_back({"thread.png", "thread.png: a close-up of the thread of line " + std::to_string(thread.programmed.line),
                           render::encodePng(render::partImage(closeUpMesh, toolpath, closeUp))});
    break;
  }
  return drawn;
}

}  // namespace

void stageRunFiles(SimulatedRun& run, const RunOptions& options, StagedOutput& out, Stopwatch& clock) {
  run.progress->stage("writing STL, VDB, the pictures and the report");
  using Path = std::filesystem::path;
  const OutputSelection& wanted = options.outputs;
  RunTimings& timing = run.figures.timing;
  // The pictures are drawn in a thread of their own while the files are written here, and
  // staged after them, so that the files are written in one order whatever the machine's
  // speed. The display is made sure of from this thread: an Xvfb started from the drawing
  // thread would end with it (it dies with the thread that started it).
  // The toolpath as drawn: bounded, whatever the program's length.
  const interp::Toolpath drawnToolpath = run.drawn ? run.drawn->toolpath(run.job.toolpath) : interp::Toolpath{};
  std::future<DrawnPictures> drawing;
  if (wanted.png) {
    render::ensureDisplay();
    drawing = std::async(std::launch::async, [&run, &drawnToolpath, &options, &timing] {
      Stopwatch drawClock;
      DrawnPictures drawn = drawPictures(run, drawnToolpath, options);
      timing.renderS = drawClock.lap();
      return drawn;
    });
  }
  Stopwatch writing;
  if (wanted.stl) out.write("part.stl", [&](const Path& file) { render::writeBinaryStl(run.part, file); });
  if (wanted.stl && run.partedOff())
    out.write("stub.stl", [&](const Path& file) { render::writeBinaryStl(run.stub, file); });
  if (wanted.csv)
    out.write("toolpath.csv", [&](const Path& file) {
      writeTextFile(file, [&](std::ostream& csv) {
        if (run.csv) run.csv->copyTo(csv);
        else interp::writeToolpathCsv(run.job.toolpath, csv);
      });
    });
  if (wanted.vtp) out.write("toolpath.vtp", [&](const Path& file) { render::writeToolpathVtp(*run.moves, file); });
  timing.writeS += writing.lap();
  if (drawing.valid()) {
    DrawnPictures drawn = drawing.get();
    writing.lap();  // not the wait for the pictures
    run.partPixels = std::move(drawn.partPixels);
    for (const DrawnPicture& picture : drawn.files) {
      const Path png = out.write(picture.file, [&](const Path& file) { render::writeFileBytes(picture.png, file); });
      run.pictures.push_back({picture.description, png});
    }
  }
  // After the pictures, not beside them: their copies of the mesh and these would add up to
  // the run's peak memory (a Φ300×600 bar at 0.2 mm: 2.53 times its grid's memory, 2.20 without).
  // report.html's shows the machine beside the part; part.glb is the part and its toolpath.
  const auto crashes = crashMarksOf(run.figures.simulation.collisions);
  if (wanted.html) run.modelGlb = render::partGlb(run.part, drawnToolpath, crashes, sceneMachine(run.job.setup, drawnToolpath));
  for (const std::string& format : options.exports) {
    out.write("part." + format, [&](const Path& file) {
      if (format == "gltf") render::writePartGltf(run.part, drawnToolpath, file);
      if (format == "glb") render::writeFileBytes(render::partGlb(run.part, drawnToolpath, crashes), file);
      if (format == "ply") render::writePartPly(run.part, file);
      if (format == "obj") render::writePartObj(run.part, file);
    });
  }
  out.syncWritten();  // under way since each file was written: most are done by now
  timing.writeS += writing.lap();
  clock.lap();
}

void stageThumbnail(const RunOptions& options, const render::RgbImage& picture, StagedOutput& out) {
  if (!options.pictures.thumbnailWidthPx || picture.rgb.empty()) return;
  out.write("thumbnail.png", [&](const std::filesystem::path& file) {
    render::writeFileBytes(render::thumbnailPng(picture, *options.pictures.thumbnailWidthPx), file);
  });
}

void useBlockRows(const SimulatedRun& run, const std::function<void(const sim::BlockRows&)>& use) {
  if (run.blockRows) return use(*run.blockRows);
  use(sim::HeldBlockRows(run.figures.simulation.blocks));
}

void stageReports(const SimulatedRun& run, const nlohmann::ordered_json& report, StagedOutput& out) {
  using Path = std::filesystem::path;
  useBlockRows(run, [&](const sim::BlockRows& blocks) {
    out.write("report.json", [&](const Path& file) { writeReport(report, blocks, file); });
    if (run.outputs.html)
      out.write("report.html", [&](const Path& file) {
        writeReportHtml(report, blocks, run.job.programText.text(), run.pictures, run.video, run.modelGlb,
                        run.steps ? run.steps->json(blocks, run.job.setup, run.job.toolpath.startPosition) : nullptr, file);
      });
  });
}

// The run keepUntilExit keeps. A variable other files could read, so that the compiler keeps
// the pointer stored and leak checkers find the run reachable from it: a function's static that
// nothing reads was optimised away, and LeakSanitizer reported the run as lost.
const SimulatedRun* keptUntilExit = nullptr;

void keepUntilExit(SimulatedRun run) {
  if (keptUntilExit == nullptr) keptUntilExit = new SimulatedRun(std::move(run));
}

double peakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB
}

}  // namespace lathesim::app
