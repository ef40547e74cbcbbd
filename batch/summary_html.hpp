#pragma once
// summary.html: the overview a teacher reads — one row per program with a thumbnail of the
// part (or, for a checked part, of its deviation picture), its status, its first error or
// warning, volumes, cycle time, collisions and the check's largest gouge and excess.
// Sortable by any column (click a heading; the order is kept in the address, #sort=-key).
// One self-contained file: the style, the script and the thumbnails are inside it; it
// loads nothing from anywhere and links only to the jobs' own files beside it.

#include <filesystem>
#include <ostream>

#include "batch/summary.hpp"

namespace lathesim::batch {

/// Writes the page; `folder` is where it will be, against which the jobs' folders (and
/// their thumbnails, read now) are relative.
void writeSummaryHtml(const BatchSummary& summary, const std::filesystem::path& folder, std::ostream& out);

}  // namespace lathesim::batch
