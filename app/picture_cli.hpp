#pragma once
// The command-line options of the pictures, shared by run and check: --views, --size,
// --animate, --gif, --pace, --frames, --video-size.

#include <CLI/CLI.hpp>

#include "app/commands.hpp"

namespace lathesim::app {

void addPictureOptions(CLI::App& command, RunOptions& options);

}  // namespace lathesim::app
