#pragma once
// The lathesim command's exit statuses, the same for every subcommand (batch sums its jobs'
// up the same way), so that a script can tell a bad program from a bad command line.

namespace lathesim::setup {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;        // a bad program, setup, drawing or manifest, or outputs not written
inline constexpr int kExitBadCommandLine = 2;  // an unknown option, a missing or malformed argument
// check: the part is not shown within the drawing's tolerance — out of it, or a figure the
// voxel cannot decide (nearer its limit than the voxel's uncertainty): never a pass.
inline constexpr int kExitOutOfTolerance = 3;
/// run, check: the program crashes (a rapid or a holder into the material, anything into the
/// chuck); the outputs are written, the crash marked in them. Over 3: a crash is the worse news.
/// Not under [sim] collisions = "warn" / --collisions warn (then 0, or 3 from check).
inline constexpr int kExitCrash = 4;
/// Ended by a signal it caught (SIGINT 130, SIGTERM 143), as a shell reports it.
inline constexpr int exitOnSignal(int signal) { return 128 + signal; }

}  // namespace lathesim::setup
