#include "batch/resources.hpp"

#include <sched.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "interp/text/file_text.hpp"
#include "interp/text/machine_evidence.hpp"
#include "setup/setup.hpp"
#include "setup/stock_option.hpp"
#include "sim/stock.hpp"

namespace lathesim::batch {
namespace {

std::optional<long long> environmentNumber(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return std::nullopt;
  char* end = nullptr;
  const long long value = std::strtoll(text, &end, 10);
  if (end == text || value <= 0) return std::nullopt;
  return value;
}

/// The bar the job will simulate, chosen as setup::loadJob chooses it: --stock, else the
/// setup's [stock], else the bar the program states, else the setup's default; nullopt if
/// the setup or --stock cannot be read (the job will stop at once on them).
std::optional<sim::StockSpec> barOf(const BatchJob& job, const setup::Setup& setup) {
  if (const auto stock = optionValues(job.settings.options, "--stock"); !stock.empty()) {
    const auto bar = setup::parseStockOption(stock.back());
    if (const auto* spec = std::get_if<sim::StockSpec>(&bar)) return *spec;
    return std::nullopt;
  }
  if (setup.stockGiven) return setup.stock;
  // The program's one walk of the lines, as the job reads it (setup::openJob), mapped rather
  // than copied; a program that cannot be read states no bar (its job stops at once).
  try {
    const interp::FileText text = interp::FileText::read(job.program);
    if (const auto stated = interp::readMachineEvidence(text.text()).stock)
      return sim::StockSpec{stated->diameterMm, stated->lengthMm, 0.0};
  } catch (const std::system_error&) {
  }
  return setup.stock;
}

}  // namespace

std::uint64_t estimatedJobBytes(const BatchJob& job) {
  std::optional<setup::Setup> setup = setup::defaultSetup();
  if (job.settings.setup) setup = setup::loadSetup(*job.settings.setup).setup;
  if (!setup) return kProcessBaseBytes;
  const std::optional<sim::StockSpec> bar = barOf(job, *setup);
  const double voxelMm = job.settings.voxelMm.value_or(setup->voxelMm.value_or(setup::kDefaultVoxelMm));
  if (!bar || !(voxelMm > 0)) return kProcessBaseBytes;
  return kProcessBaseBytes + sim::estimatedStockBytes(*bar, voxelMm);
}

int availableCpus() {
  int cpus = 1;
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) cpus = CPU_COUNT(&set);
  // Slurm without CPU binding (task/none) leaves the mask whole: trust what it allotted.
  if (auto slurm = environmentNumber("SLURM_CPUS_ON_NODE"); slurm && *slurm < cpus) cpus = static_cast<int>(*slurm);
  return cpus > 0 ? cpus : 1;
}

std::optional<std::uint64_t> availableMemoryBytes() {
  std::optional<std::uint64_t> available;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    std::istringstream fields(line);
    std::string key;
    std::uint64_t kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") available = kib * 1024;
  }
  if (auto slurmMb = environmentNumber("SLURM_MEM_PER_NODE")) {
    const std::uint64_t slurm = static_cast<std::uint64_t>(*slurmMb) << 20;
    if (!available || slurm < *available) available = slurm;
  }
  return available;
}

bool mayStart(int running, std::uint64_t runningBytes, std::uint64_t jobBytes, int slots,
              std::optional<std::uint64_t> budgetBytes) {
  if (running >= slots) return false;
  return running == 0 || !budgetBytes || runningBytes + jobBytes <= *budgetBytes;
}

}  // namespace lathesim::batch
