#pragma once
// report.html: one self-contained page per run that opens offline in any browser — the
// pictures, the summary, collisions and warnings with their lines, the program listing with
// each line's machine time and removed volume, and the part and toolpath in 3D (the GLB and
// the bundled three.js viewer inside the page). `check` adds its section.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "sim/block_rows.hpp"

namespace lathesim::app {

struct HtmlPicture {
  std::string caption;
  std::filesystem::path png;  // read and carried in the page
};

/// Writes the page for the run `report` (reportJson's, its rows `blocks` apart) of the program
/// `programText`, with `pictures` and the 3D model `glb` (empty: no 3D view).
void writeReportHtml(const nlohmann::ordered_json& report, const sim::BlockRows& blocks,
                     std::string_view programText, const std::vector<HtmlPicture>& pictures, const std::string& glb,
                     const std::filesystem::path& html);

}  // namespace lathesim::app
