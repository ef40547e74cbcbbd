#pragma once
// The 3D viewer of report.html (viewer/src/viewer.js with three.js), bundled at build time.

#include <string_view>

namespace lathesim::viewer {

/// The bundled script, ready to sit inside an HTML <script> element: it draws the GLB found in
/// <script type="application/octet-stream" id="part-model"> (base64) into #view3d.
std::string_view viewerScript();

}  // namespace lathesim::viewer
