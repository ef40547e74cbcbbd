#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <iostream>

#include "app/at_line.hpp"
#include "app/collision_checks.hpp"
#include "app/commands.hpp"
#include "app/job.hpp"
#include "app/progress.hpp"
#include "app/report.hpp"
#include "app/staged_output.hpp"
#include "app/tool_picture.hpp"
#include "interp/cycle_time.hpp"
#include "interp/toolpath_csv.hpp"
#include "render/mesh_files.hpp"
#include "render/part_image.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {
namespace {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

sim::ToolOutlines outlinesOf(const Setup& setup) {
  sim::ToolOutlines tools;
  for (const auto& tool : setup.tools) tools.emplace(tool.number, tool.outline);
  return tools;
}

}  // namespace

int runCommand(const RunOptions& options) {
  Stopwatch clock;
  RunFigures figures;
  std::optional<Job> job = loadJob(options.program, options.setup, options.dialect);
  if (!job || !cutAtLine(options.atLine, *job)) return 1;
  figures.atLine = options.atLine;
  figures.timing.parseS = clock.lap();

  const double voxel = options.voxelMm.value_or(job->setup.voxelMm.value_or(kDefaultVoxelMm));
  if (const auto problem = sim::gridProblem(job->setup.stock, voxel)) {
    std::cerr << "lathesim: error: " << *problem << '\n';
    return 1;
  }
  figures.program = options.program.string();
  figures.setup = job->setup.sourceName;
  figures.voxelMm = voxel;
  figures.moves = job->toolpath.moves.size();
  figures.cycleTimeS = interp::cycleTimeS(job->toolpath);
  figures.warnings = job->warnings;

  Progress progress(figures.program);
  sim::Stock stock(job->setup.stock, voxel);
  figures.stockVolumeMm3 = stock.volumeMm3();
  const sim::CollisionChecks checks = collisionChecksOf(job->setup);
  figures.simulation = sim::simulate(job->toolpath, outlinesOf(job->setup), stock,
                                     [&](int done, int total) { progress.update(done, total); }, &checks);
  figures.finalVolumeMm3 = stock.volumeMm3();
  figures.timing.simulateS = clock.lap();
  for (const auto& w : figures.simulation.warnings) {
    figures.warnings.push_back(job->warningAt(w.line, w.column, w.message));
    std::cerr << interp::format(figures.warnings.back()) << '\n';
  }

  progress.stage("meshing");
  const TriangleMesh part = stock.mesh(kExportAdaptivity);
  figures.meshVolumeMm3 = enclosedVolumeMm3(part);
  figures.meshTriangles = part.triangles.size();
  figures.timing.meshS = clock.lap();

  progress.stage("writing STL, VDB and the render");
  StagedOutput out(options.out);
  render::writeBinaryStl(part, out.stage("part.stl"));
  {
    std::ofstream csv(out.stage("toolpath.csv"));
    interp::writeToolpathCsv(job->toolpath, csv);
  }
  render::writeToolpathVtp(job->toolpath, out.stage("toolpath.vtp"));
  stock.writeVdb(out.stage("stock.vdb"));
  render::PartImageOptions image;
  image.title = figures.program;
  image.tool = toolPictureAtEnd(job->setup, job->toolpath);
  render::writePartImagePng(part, job->toolpath, image, out.stage("part.png"));
  figures.timing.renderS = clock.lap();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  figures.peakMemoryMb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB
  writeReportJson(figures, out.stage("report.json"));
  out.commit();
  progress.stage("done");
  progress.finish();

  std::cout << figures.program << ": " << figures.moves << " moves, final volume " << figures.finalVolumeMm3
            << " mm³ (removed " << figures.stockVolumeMm3 - figures.finalVolumeMm3 << " mm³) at " << voxel
            << " mm voxels, " << figures.simulation.collisions.size() << " collision(s); outputs in "
            << options.out.string() << "/\n";
  for (const auto& c : figures.simulation.collisions)
    std::cout << "  collision: line " << c.line << ", " << c.kind << ", " << c.volumeMm3 << " mm³\n";
  return 0;
}

int expandCommand(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setup,
                  std::optional<interp::Dialect> dialect) {
  const std::optional<Job> job = loadJob(program, setup, dialect);
  if (!job) return 1;
  interp::writeToolpathCsv(job->toolpath, std::cout);
  return 0;
}

}  // namespace lathesim::app
