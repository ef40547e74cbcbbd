#include "app/run_pipeline.hpp"

#include <sys/resource.h>

#include <iostream>

#include "app/at_line.hpp"
#include "job/collision_checks.hpp"
#include "app/tool_picture.hpp"
#include "measure/volume_checks.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/toolpath_csv.hpp"
#include "render/mesh_files.hpp"
#include "render/part_image.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

sim::ToolOutlines outlinesOf(const job::Setup& setup) {
  sim::ToolOutlines tools;
  for (const auto& tool : setup.tools) tools.emplace(tool.number, tool.outline);
  return tools;
}

namespace {

// A warning for the report, also printed on stderr; line 0 when it concerns the whole run.
void warn(SimulatedRun& run, int line, int column, const std::string& message) {
  run.figures.warnings.push_back(run.job.warningAt(line, column, message));
  std::cerr << interp::format(run.figures.warnings.back()) << '\n';
}
void warn(SimulatedRun& run, const std::string& message) { warn(run, 0, 0, message); }

}  // namespace

std::optional<SimulatedRun> simulateProgram(const RunOptions& options, Stopwatch& clock) {
  std::optional<job::Job> loaded = job::loadJob(jobRequestOf(options));
  if (!loaded || !cutAtLine(options.atLine, *loaded)) return std::nullopt;
  SimulatedRun run;
  run.job = std::move(*loaded);
  RunFigures& figures = run.figures;
  figures.atLine = options.atLine;
  figures.timing.parseS = clock.lap();

  const job::Setup& setup = run.job.setup;
  const double voxel = options.voxelMm.value_or(setup.voxelMm.value_or(kDefaultVoxelMm));
  if (const auto problem = sim::gridProblem(setup.stock, voxel)) {
    std::cerr << "lathesim: error: " << *problem << '\n';
    return std::nullopt;
  }
  figures.program = options.program.string();
  figures.setup = setup.sourceName;
  figures.control = setup.control;
  figures.travel = job::travelOf(setup);
  figures.voxelMm = voxel;
  figures.moves = run.job.toolpath.moves.size();
  figures.cycleTimeS = interp::cycleTimeS(run.job.toolpath);
  figures.warnings = run.job.warnings;
  figures.notes = run.job.notes;
  figures.stops = run.job.toolpath.stops;

  run.progress = std::make_unique<Progress>(figures.program);
  run.stock = std::make_unique<sim::Stock>(setup.stock, voxel);
  figures.stockVolumeMm3 = run.stock->volumeMm3();
  if (auto problem = measure::barVolumeProblem(setup.stock, figures.stockVolumeMm3, voxel)) warn(run, *problem);
  const sim::CollisionChecks checks = job::collisionChecksOf(setup);  // holders and the chuck
  figures.simulation = sim::simulate(run.job.toolpath, outlinesOf(setup), *run.stock,
                                     [&](int done, int total) { run.progress->update(done, total); }, &checks);
  figures.finalVolumeMm3 = run.stock->volumeMm3();
  figures.timing.simulateS = clock.lap();
  for (const auto& w : figures.simulation.warnings) warn(run, w.line, w.column, w.message);
  return run;
}

void meshPart(SimulatedRun& run, Stopwatch& clock) {
  run.progress->stage("meshing");
  RunFigures& figures = run.figures;
  run.part = run.stock->mesh(kExportAdaptivity);
  // The level set's volume is checked against the whole mesh; crumbs thinner than a voxel
  // are then left out of the STL, and what they held is reported.
  if (auto problem = measure::meshVolumeProblem(figures.finalVolumeMm3, run.part, figures.voxelMm)) warn(run, *problem);
  figures.meshCrumbs = dropCrumbs(run.part, figures.voxelMm);
  if (auto problem = measure::meshClosureProblem(run.part)) warn(run, *problem);
  figures.meshVolumeMm3 = enclosedVolumeMm3(run.part);
  figures.volumeToleranceMm3 = sim::volumeToleranceMm3(surfaceAreaMm2(run.part), figures.voxelMm);
  figures.meshTriangles = run.part.triangles.size();
  figures.timing.meshS = clock.lap();
}

void stageRunFiles(SimulatedRun& run, StagedOutput& out, Stopwatch& clock) {
  run.progress->stage("writing STL, VDB and the render");
  using Path = std::filesystem::path;
  out.write("part.stl", [&](const Path& file) { render::writeBinaryStl(run.part, file); });
  out.write("toolpath.csv", [&](const Path& file) {
    writeTextFile(file, [&](std::ostream& csv) { interp::writeToolpathCsv(run.job.toolpath, csv); });
  });
  out.write("toolpath.vtp", [&](const Path& file) { render::writeToolpathVtp(run.job.toolpath, file); });
  out.write("stock.vdb", [&](const Path& file) { run.stock->writeVdb(file); });
  render::PartImageOptions image;
  image.title = run.figures.program;
  image.tool = toolPictureAtEnd(run.job.setup, run.job.toolpath);
  out.write("part.png", [&](const Path& file) { render::writePartImagePng(run.part, run.job.toolpath, image, file); });
  run.figures.timing.renderS = clock.lap();
}

double peakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB
}

}  // namespace lathesim::app
