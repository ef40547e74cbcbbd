#pragma once
// `check`'s findings as an inspection report says them: a diameter as a diameter, a face as
// a Z, each with its uncertainty at the voxel, the tolerance that applied and where it came
// from, the verdict (an undecided one naming the voxel that would decide it), and the lines
// that made the surface there with their text.

#include <functional>
#include <string>
#include <vector>

#include "measure/deviation.hpp"
#include "measure/size_check.hpp"
#include "measure/thread_check.hpp"

namespace lathesim::app {

/// The text of a program line, for quoting a block.
using BlockText = std::function<std::string(int line)>;

/// "+0/−0.021", "±0.2", "+0.025/0" (mm).
std::string limitsText(double upperMm, double lowerMm);

/// "Ø19.500 ±0.010 measured at Z-8.000 (drawn Ø20.000 +0/−0.021, h7, drawing line 7): 0.500
/// undersize, 0.479 beyond its limit: OUT; made by line 17 `X19.5 Z-1.`"
std::string sizeText(const measure::SizeCheck& size, double voxelMm, const BlockText& block);

/// "excess 0.331 ±0.025 mm normal to the drawing at Z-10.000 Ø20.000 (…), allowed −0.010/+0 there, 0.321 beyond: OUT; …"
std::string regionText(const measure::DeviationRegion& region, double uncertaintyMm, double voxelMm, const BlockText& block);

/// What the verdict says: "within", "OUT", or "undecided at this voxel; rerun with --voxel V".
std::string verdictText(measure::Verdict verdict, double outsideMm, double voxelMm, double uncertaintyMm);

/// "made by line 17 `X19.5 Z-1.`" (or lines …), empty for none.
std::string madeByText(const std::vector<int>& lines, const BlockText& block);

/// The whole check's verdict: out if anything is out (a thread not as called out included),
/// else undecided if anything is, else within.
measure::Verdict overallVerdict(const std::vector<measure::SizeCheck>& sizes, const measure::DeviationReport& deviation,
                                const std::vector<measure::ThreadCheck>& threads);

}  // namespace lathesim::app
