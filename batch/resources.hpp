#pragma once
// How many jobs a machine can run at once: its cores, and its memory against what each
// job's grid needs (estimated up front from the stock and voxel, as `run` checks a grid).

#include <cstdint>
#include <optional>

#include "batch/batch_job.hpp"

namespace lathesim::batch {

/// What one lathesim process needs besides its level set, measured on this machine: the
/// peak of a run on a Φ40×50 bar at 0.5 mm (whose level set is under 10 MB) was 230–260 MB
/// — the libraries, VTK's render window under Mesa llvmpipe, the mesh and its writers.
inline constexpr std::uint64_t kProcessBaseBytes = 280ull << 20;

/// The memory `job` is expected to take at its peak (bytes): its bar's level set at its
/// voxel size (sim::estimatedStockBytes, which allows for the surface cutting adds) plus
/// kProcessBaseBytes. The bar is --stock's, the setup's, the program's own statement or the
/// default, as `run` chooses. A setup or --stock that cannot be read counts as the process
/// base alone (the job will stop at once with its diagnostics).
std::uint64_t estimatedJobBytes(const BatchJob& job);

/// CPUs this process may use: its affinity mask, and under Slurm the CPUs it was given.
int availableCpus();

/// Memory the batch may fill (bytes): MemAvailable from /proc/meminfo, capped by a Slurm
/// job's --mem; nullopt if unknown.
std::optional<std::uint64_t> availableMemoryBytes();

/// Whether a job needing `jobBytes` may start beside `running` jobs that need `runningBytes`
/// together: a free slot, and room in `budgetBytes` (when known). A job always may start
/// alone: if it is too big for the machine, its own run says so.
bool mayStart(int running, std::uint64_t runningBytes, std::uint64_t jobBytes, int slots,
              std::optional<std::uint64_t> budgetBytes);

}  // namespace lathesim::batch
