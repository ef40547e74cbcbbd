#include "batch/resources.hpp"

#include <sched.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "job/setup.hpp"
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

}  // namespace

std::uint64_t estimatedJobBytes(const BatchJob& job) {
  std::optional<job::Setup> setup = job::defaultSetup();
  if (job.settings.setup) setup = job::loadSetup(*job.settings.setup).setup;
  if (!setup) return kProcessBaseBytes;
  const double voxelMm = job.settings.voxelMm.value_or(setup->voxelMm.value_or(job::kDefaultVoxelMm));
  if (!(voxelMm > 0)) return kProcessBaseBytes;
  return kProcessBaseBytes + sim::estimatedStockBytes(setup->stock, voxelMm);
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
