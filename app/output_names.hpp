#pragma once
// Every file name lathesim writes into --out, in one list. StagedOutput stages no other name
// (a new output cannot be left off the list), and a run removes the files on the list that a
// previous run left in the folder and it does not write itself: --out holds one run. Any other
// file there is the user's and is left alone.

#include <string>
#include <string_view>
#include <vector>

#include "render/part_image.hpp"

namespace lathesim::app {

/// part.png, part-front.png, part-section.png.
std::string pictureFileName(render::PartView view);

/// The names, in no particular order.
const std::vector<std::string>& outputFileNames();

/// Whether `name` (a file name, no folder) is one of them.
bool isOutputFileName(std::string_view name);

/// Whether `name` is a file `lathesim batch` keeps in a job's folder beside the run's outputs
/// (the job's log, its input stamp): not the run's to remove, nor the user's.
bool isBatchFileName(std::string_view name);

}  // namespace lathesim::app
