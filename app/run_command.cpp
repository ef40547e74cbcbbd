#include <iostream>

#include "app/commands.hpp"
#include "app/run_pipeline.hpp"
#include "setup/setup.hpp"
#include "interp/base/printable_text.hpp"

namespace lathesim::app {

int runCommand(const RunOptions& options) {
  Stopwatch clock;
  StagedOutput out(options.out);
  std::optional<SimulatedRun> run = simulateProgram(options, clock, &out);
  if (!run) return setup::kExitBadInput;
  std::future<double> stockFile = stageStockFile(*run, out);
  meshPart(*run, clock);
  finishStockFile(*run, stockFile);  // before the other files: they are written in one order, whatever the machine's speed
  stageRunFiles(*run, options, out, clock);
  RunFigures& figures = run->figures;
  figures.peakMemoryMb = peakMemoryMb();
  figures.timing.totalS = clock.total();
  // Outside the timings: a batch's own work, which its benchmark counts as per-job overhead.
  stageThumbnail(options, run->partPixels, out);
  stageReports(*run, reportJson(figures), out);
  out.commit();
  run->progress->stage("done");
  run->progress->finish();

  std::cout << interp::printable(figures.program) << " (" << interp::describeMachine(figures.machine) << "): " << figures.moves << " moves, " << skippedSummary(figures.skipped) << "final volume " << figures.finalVolumeMm3
            << " mm³ (removed " << figures.stockVolumeMm3 - figures.finalVolumeMm3 << " mm³) at " << figures.voxelMm
            << " mm voxels, " << figures.simulation.collisions.size() << " collision(s); outputs in "
            << interp::printable(options.out.string()) << "/\n";
  if (!figures.assumed.empty()) {  // said of the file looked in, or of the defaults when none was
    const std::string& setupName = run->job.setup.sourceName;
    const std::string why = setupName == setup::defaultSetup().sourceName
                                ? "no setup was given (--setup), so lathesim's default setup says"
                                : interp::printable(setupName) + " does not say";
    std::cout << "  assumed, as " << why << ": " << setup::assumptionsText(figures.assumed) << '\n';
  }
  if (!figures.simulation.partOffs.empty()) {
    const sim::PartOff& off = figures.simulation.partOffs.front();
    std::cout << "  parted off at line " << off.line << ", Z" << off.zMm << ": the part " << off.volumeMm3
              << " mm³ (part.stl), the stub " << figures.stubVolumeMm3 << " mm³ (stub.stl)\n";
  }
  for (const auto& thread : figures.threads) std::cout << "  " << threadSummary(thread) << '\n';
  const bool crashed = figures.crashed();
  keepUntilExit(std::move(*run));
  return crashed ? setup::kExitCrash : setup::kExitOk;
}

setup::JobRequest jobRequestOf(const RunOptions& options) {
  return {options.program, options.setup, options.overrides, options.programDirectories, options.stock};
}

}  // namespace lathesim::app
