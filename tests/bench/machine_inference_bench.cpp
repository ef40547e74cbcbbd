// The cost of reading the machine from the program (interp/text/machine_evidence.hpp and
// interp/text/machine_choice.hpp) against `lathesim expand` of the same program, measured
// in one run: a generated program of 20,000 blocks (a system-B header, then feed moves back
// and forth along a Φ40 bar). The bound: the inference under 5 % of the expand.
//   BM_Expand           the whole expand as the command runs it: the job opened (the evidence
//                       read, the machine chosen), the program interpreted, the CSV written
//   BM_ExpandStated     the same with --dialect and --control given (no choice to make; the
//                       evidence is still read for its warnings and the foreign families)
//   BM_Inference        the evidence read and the machine chosen, alone

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "interp/text/machine_choice.hpp"
#include "interp/text/file_text.hpp"
#include "interp/text/machine_evidence.hpp"
#include "interp/output/toolpath_csv_spool.hpp"
#include "setup/job.hpp"

namespace {

using namespace lathesim;

constexpr int kBlocks = 20'000;

const std::filesystem::path& program() {
  static const std::filesystem::path path = [] {
    const auto file = std::filesystem::temp_directory_path() / "lathesim-inference-bench.nc";
    std::ofstream out(file);
    out << "%\nO1000 (GENERATED)\nG21 G40 G90 G95\nG92 S3000\nT0101\nG96 S200 M03\nG00 X42. Z2.\n";
    for (int i = 0; i < kBlocks; ++i) {
      const double x = 38.0 - 0.001 * (i % 1000);
      out << fmt::format("N{} G01 X{:.3f} Z{:.3f} F0.2\n", i + 10, x, i % 2 == 0 ? -30.0 : 1.0);
    }
    out << "G00 X200. Z200.\nM30\n%\n";
    return file;
  }();
  return path;
}

void expand(benchmark::State& state, bool stated) {
  setup::JobRequest request;
  request.program = program();
  if (stated) {
    request.overrides.dialect = interp::Dialect::FanucB;
    request.overrides.controlPreset = "gsk980tdi";
  }
  for (auto _ : state) {
    interp::ToolpathCsvSpool csv;
    if (!setup::loadJob(request, csv).value) state.SkipWithError("the program did not run");
    benchmark::DoNotOptimize(csv);
  }
}

void BM_Expand(benchmark::State& state) { expand(state, false); }
void BM_ExpandStated(benchmark::State& state) { expand(state, true); }

void BM_Inference(benchmark::State& state) {
  const interp::FileText text = interp::FileText::read(program());
  for (auto _ : state) {
    const interp::MachineEvidence evidence = interp::readMachineEvidence(text.text());
    const interp::MachineChoice choice = interp::chooseMachine(evidence, {});
    benchmark::DoNotOptimize(choice);
  }
}

BENCHMARK(BM_Expand)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ExpandStated)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_Inference)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
