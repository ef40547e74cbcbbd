#pragma once
// Tools a program names in its comments, for the T words no setup defines. A T block's own
// comments are read first, then the comment lines directly above it:
//   an ISO insert      (CNMG 120408), (VBMT160404 R0.4), with its ISO holder when the comment
//                      names one (PCLNR2525M12), else the usual holder for the insert's shape
//                      (C, W: L style 95°; D, V: J 93°; T: G 90°; S: B 75°), 25×25, right hand
//   a grooving or      (GROOVE 3MM), (PARTING W4), (CUT-OFF 2.5 MM): a blade that wide with
//   parting blade      square corners, deep enough to part the bar (its radius + 5 mm), tip 3
//   a drill            (DRILL 12), (12MM DRILL), (Ø8.5 DRILL): 118° point, 10 × D long
//   a threading tool   (THREAD 60 DEG), (THREADING P1.5), (THREAD M20X1.5): the angle (60 when
//                      not said) and the pitch; without a pitch, a partial-profile insert
//                      (AG, 0.5–3 mm) drawn for 3 mm with the nose of the smallest pitch
// Each mounted tool comes with a warning saying which comment it came from.

#include <optional>
#include <string>
#include <vector>

#include "setup/setup.hpp"

namespace lathesim::setup {

struct CommentTool {
  ToolDefinition tool;
  std::string description;  // what was mounted, e.g. "CNMG120408 in PCLNR2525M12 (the holder assumed for a C insert)"
  std::vector<std::string> warnings;  // from building the tool (an insert that does not fit its holder …)
};

/// The tool numbered `number` that `comment` names, or nullopt when it names none.
/// `barDiameterMm` sizes a parting blade's depth.
std::optional<CommentTool> toolNamedIn(const std::string& comment, int number, double barDiameterMm);

}  // namespace lathesim::setup
