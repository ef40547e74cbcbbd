#pragma once
// report.html: one self-contained page per run that opens offline in any browser — the
// pictures, the summary, collisions and warnings with their lines, the program listing with
// each line's machine time and removed volume, and the part and toolpath in 3D (the GLB and
// the bundled three.js viewer inside the page). `check` adds its section.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "interp/base/paged_text.hpp"
#include "sim/block_rows.hpp"

namespace lathesim::app {

struct HtmlPicture {
  std::string caption;
  std::filesystem::path png;  // read and carried in the page
};

/// Writes the page for the run `report` (reportJson's, its rows `blocks` apart) of the program
/// `programText`, with `pictures` and the 3D model `glb` (empty: no 3D view). The listing is
/// written as the text and the rows are read, holding figures only for the lines run more
/// than once or out of order: a long program's page takes no more memory than a short one's.
/// `steps` (StepRecording::json) adds the stepping through the program (app/report_steps.hpp).
void writeReportHtml(const nlohmann::ordered_json& report, const sim::BlockRows& blocks,
                     const interp::PagedText& programText, const std::vector<HtmlPicture>& pictures,
                     const std::string& glb, const nlohmann::ordered_json& steps, const std::filesystem::path& html);

}  // namespace lathesim::app
