#include "app/output_names.hpp"

#include <algorithm>

#include "batch/batch_runner.hpp"
#include "batch/input_stamp.hpp"

namespace lathesim::app {

std::string pictureFileName(render::PartView view) {
  if (view == render::PartView::Iso) return "part.png";
  return "part-" + std::string(render::viewName(view)) + ".png";
}

const std::vector<std::string>& outputFileNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all{
        "part.stl",     "stub.stl",      "stock.vdb",   "toolpath.csv",  "toolpath.vtp",  // run_pipeline.cpp
        "thread.png",   "thumbnail.png", "report.json", "report.html",                    // run_pipeline.cpp
        "cut.mp4",      "cut.gif",                                                        // cut_recording.cpp
        "deviation.png", "section.png",                                                   // check_command.cpp
    };
    for (const render::PartView view : {render::PartView::Iso, render::PartView::Front, render::PartView::Section})
      all.push_back(pictureFileName(view));
    for (const char* format : {"gltf", "glb", "ply", "obj"}) all.push_back(std::string("part.") + format);  // --export
    return all;
  }();
  return names;
}

bool isOutputFileName(std::string_view name) {
  const auto& names = outputFileNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool isBatchFileName(std::string_view name) {
  return name == batch::kJobLogFileName || name == batch::kStampFileName ||
         name == std::string(batch::kStampFileName) + ".tmp";
}

}  // namespace lathesim::app
