#pragma once
// report.html's "Step through the program": a block slider with single-step keys (← →,
// Home/End) and buttons to the next cut, collision or warning; the listing's line highlighted
// (and a clicked line jumped to); the stock's section after that block drawn with the toolpath
// so far and the tool (insert and holder, at their real size) where the block leaves it; the
// block's removed volume, time, feed, S and rpm, and the running totals. The step is kept in
// the address (#step=N), so a reload (lathesim watch) comes back to it. Plain script, no
// library: the page still opens offline.

#include <nlohmann/json.hpp>
#include <string>

namespace lathesim::app {

/// The section for `steps` (StepRecording::json) of the run `report` (its collisions' and
/// warnings' lines); empty when `steps` is null or holds no step. A long program's page says
/// how many blocks each step covers, and when its toolpath is not drawn.
std::string stepSection(const nlohmann::ordered_json& steps, const nlohmann::ordered_json& report);

/// Its script, for the end of the page (it reads the listing's rows).
std::string stepScript();

}  // namespace lathesim::app
