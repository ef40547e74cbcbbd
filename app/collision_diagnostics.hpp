#pragma once
// A collision said as a diagnostic at its block: an error (a crash fails the run, exit status
// setup::kExitCrash), or a warning under [sim] collisions = "warn" / --collisions warn.

#include <string>
#include <vector>

#include "interp/base/diagnostic.hpp"
#include "setup/job.hpp"
#include "render/crash_mark.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

/// What happened, in plain words: "rapid into the stock removes 249.7 mm³; the tool ends at
/// X38 Z-1".
std::string collisionMessage(const sim::Collision& collision);

/// The collision at its block (with the block's text, for the caret display): an error, or a
/// warning when the setup says collisions only warn.
interp::Diagnostic collisionDiagnostic(const setup::Job& job, const sim::Collision& collision);

/// Each collision as the pictures, the video and the 3D view mark it: "crash, line 8".
render::CrashMark crashMarkOf(const sim::Collision& collision);
std::vector<render::CrashMark> crashMarksOf(const std::vector<sim::Collision>& collisions);

}  // namespace lathesim::app
