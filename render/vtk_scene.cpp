// The VTK pieces the pictures share (see vtk_scene.hpp).

#include "render/vtk_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include "render/scene_export.hpp"

namespace lathesim::render {

vtkSmartPointer<vtkPolyDataMapper> shadedMapper(vtkPolyData* data, double featureAngleDeg) {
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(data);
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->SplittingOn();
  normals->SetFeatureAngle(featureAngleDeg);
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(normals->GetOutputPort());
  return mapper;
}

/// The mesh as VTK polydata, copied in bulk (meshes have millions of triangles).
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh) {
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertices.size()));
  float* xyz = coordinates->GetPointer(0);
  for (const Eigen::Vector3f& v : mesh.vertices) {
    *xyz++ = v.x();
    *xyz++ = v.y();
    *xyz++ = v.z();
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  const auto triangleCount = static_cast<vtkIdType>(mesh.triangles.size());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(triangleCount + 1);
  for (vtkIdType i = 0; i <= triangleCount; ++i) offsets->SetValue(i, 3 * i);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * triangleCount);
  vtkIdType* ids = connectivity->GetPointer(0);
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t index : t) {
      if (index >= mesh.vertices.size()) {
        throw std::runtime_error("part mesh: triangle refers to vertex " + std::to_string(index) +
                                 " of " + std::to_string(mesh.vertices.size()));
      }
      *ids++ = static_cast<vtkIdType>(index);
    }
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(polys);
  return polyData;
}

void frame(vtkCamera* camera, const View& view, const Extent& e, double aspect) {
  const Eigen::Vector3d centre = view.right * ((e.minRight + e.maxRight) / 2) +
                                 view.up * ((e.minUp + e.maxUp) / 2) +
                                 view.towardsViewer * ((e.minDepth + e.maxDepth) / 2);
  const double halfWidth = std::max((e.maxRight - e.minRight) / 2, 1e-3);
  const double halfHeight = std::max((e.maxUp - e.minUp) / 2, 1e-3);
  const double depth = std::max({e.maxDepth - e.minDepth, halfWidth, halfHeight, 1.0});

  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre.data());
  const Eigen::Vector3d eye = centre + view.towardsViewer * (2.0 * depth);
  camera->SetPosition(eye.data());
  camera->SetViewUp(view.up.data());
  camera->SetParallelScale(1.05 * std::max(halfHeight, halfWidth / aspect));
  camera->SetClippingRange(0.5 * depth, 3.5 * depth);
}

void applyFrame(vtkCamera* camera, const PictureFrame& f) {
  const View& view = f.view;
  const double depth = std::max({f.maxDepthMm - f.minDepthMm, f.widthPx / f.pxPerMm, f.heightPx / f.pxPerMm, 1.0});
  const Eigen::Vector3d centre =
      view.right * f.centreMm.x() + view.up * f.centreMm.y() + view.towardsViewer * ((f.minDepthMm + f.maxDepthMm) / 2);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre.data());
  const Eigen::Vector3d eye = centre + view.towardsViewer * (2.0 * depth);
  camera->SetPosition(eye.data());
  camera->SetViewUp(view.up.data());
  camera->SetParallelScale(f.heightPx / 2.0 / f.pxPerMm);
  camera->SetClippingRange(0.5 * depth, 3.5 * depth);
}

vtkNew<vtkTextActor> cornerText(const std::string& text, int fontPx,
                                const std::array<double, 3>& colour) {
  vtkNew<vtkTextActor> actor;
  actor->SetInput(text.c_str());
  vtkTextProperty* p = actor->GetTextProperty();
  p->SetFontSize(fontPx);
  p->SetFontFamilyToArial();
  p->SetColor(colour[0], colour[1], colour[2]);
  return actor;
}

RgbImage windowImage(vtkRenderWindow* window) {
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();  // the back buffer holds the frame just rendered: a second render would cost as much again
  grab->Update();
  vtkImageData* grabbed = grab->GetOutput();
  const int* size = grabbed->GetDimensions();
  const auto* pixels = static_cast<const unsigned char*>(grabbed->GetScalarPointer());
  RgbImage image{size[0], size[1], {}};
  image.rgb.assign(pixels, pixels + static_cast<std::size_t>(size[0]) * static_cast<std::size_t>(size[1]) * 3);
  return image;
}

void writeWindowPng(vtkRenderWindow* window, const std::filesystem::path& png) {
  // Encoded in memory and written here, so a bad path gives our message, not VTK's
  // ("Ran out of disk space") on stderr.
  writeFileBytes(encodePng(windowImage(window)), png);
}

}  // namespace lathesim::render
