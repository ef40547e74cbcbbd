#pragma once
// Inside render only: the VTK pieces the pictures share — the mesh as polydata, the view of
// a turned part (spindle axis across, end face showing), its framing, and corner text.

#include <array>
#include <filesystem>
#include <string>

#include <Eigen/Core>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include "geometry/triangle_mesh.hpp"
#include "render/picture_frame.hpp"
#include "render/rgb_image.hpp"

namespace lathesim::render {

/// The mesh as VTK polydata, copied in bulk (meshes have millions of triangles).
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh);

/// A mapper that shades `data` smoothly but keeps the shoulders of a turned part crisp:
/// point normals split at edges sharper than `featureAngleDeg`. The meshes are consistently
/// oriented, so there is no reorientation pass.
inline constexpr double kShoulderFeatureAngleDeg = 35.0;
vtkSmartPointer<vtkPolyDataMapper> shadedMapper(vtkPolyData* data, double featureAngleDeg = kShoulderFeatureAngleDeg);

/// Parallel camera on `view`, framing `e` tightly (5 % margin) in a viewport of
/// `aspect` = width / height. Parallel projection keeps the profile true to scale.
void frame(vtkCamera* camera, const View& view, const Extent& e, double aspect);

/// Parallel camera showing exactly `f` (its centre, scale and depth).
void applyFrame(vtkCamera* camera, const PictureFrame& f);

vtkNew<vtkTextActor> cornerText(const std::string& text, int fontPx, const std::array<double, 3>& colour);

/// Renders `window` (off-screen, already sized and populated) and returns its pixels.
RgbImage windowImage(vtkRenderWindow* window);

/// The same, encoded as a PNG and written to `png`. Throws std::runtime_error if it cannot be
/// encoded or written.
void writeWindowPng(vtkRenderWindow* window, const std::filesystem::path& png);

}  // namespace lathesim::render
