#include "render/part_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include "render/move_points.hpp"
#include "render/offscreen_display.hpp"
#include "render/tool_actor.hpp"

namespace lathesim::render {
namespace {

// Colours (RGB 0–1). The test relies on feeds being clearly blue and rapids clearly red.
constexpr std::array<double, 3> kFeedColour{0.05, 0.25, 0.95};
constexpr std::array<double, 3> kRapidColour{0.90, 0.08, 0.08};
constexpr std::array<double, 3> kMetalColour{0.74, 0.76, 0.79};
constexpr double kLineWidthPx = 2.0;
// The camera turns this far about the vertical (X) axis from square-on, towards +Z, so the
// end face shows. Turning about X keeps the spindle axis horizontal, and with a parallel
// projection the toolpath plane (y = 0) projects onto the part's top silhouette exactly.
constexpr double kAzimuthDeg = 22.0;
// The tool's slabs are this thick, as a fraction of the picture's diagonal (mm): enough to
// read as solid, thin enough to stay in the meridian plane.
constexpr double kToolThicknessPerSize = 0.012;

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

/// The toolpath as lines at (radius, 0, Z): feeds whole, arcs as chords, rapids cut into
/// dashes of `dashMm` with gaps of half that (core-profile OpenGL has no line stipple).
vtkSmartPointer<vtkPolyData> toolpathLines(const interp::Toolpath& toolpath, double dashMm) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetName("colour");
  auto addSegment = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const std::array<double, 3>& colour) {
    const vtkIdType first = points->InsertNextPoint(a.x(), 0.0, a.y());
    const vtkIdType second = points->InsertNextPoint(b.x(), 0.0, b.y());
    const vtkIdType ids[2] = {first, second};
    lines->InsertNextCell(2, ids);
    colours->InsertNextTuple3(255.0 * colour[0], 255.0 * colour[1], 255.0 * colour[2]);
  };
  for (const interp::Move& move : toolpath.moves) {
    if (interp::isCutting(move.kind)) {
      const std::vector<RZ> drawn = movePoints(move);
      for (std::size_t i = 1; i < drawn.size(); ++i) addSegment(drawn[i - 1], drawn[i], kFeedColour);
      continue;
    }
    const Eigen::Vector2d delta = move.to - move.from;
    const double length = delta.norm();
    if (length == 0.0) continue;
    const double period = 1.5 * dashMm;
    const auto dashes = static_cast<long>(std::ceil(length / period));
    for (long i = 0; i < dashes; ++i) {
      const double begin = static_cast<double>(i) * period;
      const double end = std::min(begin + dashMm, length);
      addSegment(move.from + delta * (begin / length), move.from + delta * (end / length),
                 kRapidColour);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetCellData()->SetScalars(colours);
  return polyData;
}

/// The view: looking at the XZ plane from +Y, turned towards +Z by kAzimuthDeg, X up.
struct View {
  Eigen::Vector3d towardsViewer, up, right;
};
View makeView() {
  const double a = kAzimuthDeg * M_PI / 180.0;
  View v;
  v.towardsViewer = Eigen::Vector3d(0.0, std::cos(a), std::sin(a));
  v.up = Eigen::Vector3d(1.0, 0.0, 0.0);
  v.right = v.up.cross(v.towardsViewer);  // (0, −sin, cos): +Z to the right
  return v;
}

/// Extent of everything drawn, along the view's axes (mm).
struct Extent {
  double minRight = std::numeric_limits<double>::infinity(), maxRight = -minRight;
  double minUp = minRight, maxUp = -minRight;
  double minDepth = minRight, maxDepth = -minRight;
  bool empty() const { return !(minRight <= maxRight); }
  void include(const View& view, const Eigen::Vector3d& p) {
    const double r = p.dot(view.right), u = p.dot(view.up), d = p.dot(view.towardsViewer);
    minRight = std::min(minRight, r), maxRight = std::max(maxRight, r);
    minUp = std::min(minUp, u), maxUp = std::max(maxUp, u);
    minDepth = std::min(minDepth, d), maxDepth = std::max(maxDepth, d);
  }
};

/// Parallel camera on `view`, framing `e` tightly (5 % margin) in a viewport of
/// `aspect` = width / height. Parallel projection keeps the profile true to scale.
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

}  // namespace

void writePartImagePng(const TriangleMesh& part, const interp::Toolpath& toolpath,
                       const PartImageOptions& options, const std::filesystem::path& png) {
  if (options.widthPx <= 0 || options.heightPx <= 0) {
    throw std::runtime_error("part image: size must be positive, not " +
                             std::to_string(options.widthPx) + "×" +
                             std::to_string(options.heightPx));
  }
  // Before any VTK window exists: without a reachable X server VTK aborts the process.
  ensureDisplay();

  const View view = makeView();
  Extent extent;
  for (const Eigen::Vector3f& v : part.vertices) extent.include(view, v.cast<double>());
  for (const interp::Move& m : toolpath.moves)
    for (const RZ& p : movePoints(m)) extent.include(view, Eigen::Vector3d(p.x(), 0.0, p.y()));
  // The insert is framed; a long holder shank may run out of the picture.
  if (options.tool) {
    for (const RZ& p : options.tool->insert) {
      const RZ at = options.tool->position + p;
      extent.include(view, Eigen::Vector3d(at.x(), 0.0, at.y()));
    }
  }
  if (extent.empty()) extent.include(view, Eigen::Vector3d::Zero());
  const double sizeMm = std::hypot(extent.maxRight - extent.minRight, extent.maxUp - extent.minUp);

  vtkNew<vtkRenderer> scene;
  scene->GradientBackgroundOn();
  scene->SetBackground(0.80, 0.83, 0.87);   // bottom
  scene->SetBackground2(1.00, 1.00, 1.00);  // top
  scene->UseFXAAOn();
  vtkNew<vtkLightKit> lights;
  lights->AddLightsToRenderer(scene);

  if (!part.triangles.empty()) {
    // Smooth shading, but keep the shoulders of a turned part crisp: normals split at edges
    // sharper than 35°. The mesh is consistently oriented, so no reorientation pass.
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(toPolyData(part));
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->SplittingOn();
    normals->SetFeatureAngle(35.0);
    normals->ConsistencyOff();
    normals->AutoOrientNormalsOff();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* metal = actor->GetProperty();
    metal->SetInterpolationToPhong();
    metal->SetColor(kMetalColour[0], kMetalColour[1], kMetalColour[2]);
    metal->SetAmbient(0.15);
    metal->SetDiffuse(0.75);
    metal->SetSpecular(0.45);
    metal->SetSpecularPower(40.0);
    scene->AddActor(actor);
  }

  if (options.tool) {
    for (const auto& actor : toolActors(*options.tool, std::max(sizeMm * kToolThicknessPerSize, 0.2)))
      scene->AddActor(actor);
  }

  // The toolpath lies in the part's meridian plane, mostly inside or on the part; it is drawn
  // in a second layer with the same camera and a fresh depth buffer, so it is always on top.
  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  overlay->SetActiveCamera(scene->GetActiveCamera());
  if (!toolpath.moves.empty()) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(toolpathLines(toolpath, std::max(sizeMm / 120.0, 1e-3)));
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetLineWidth(kLineWidthPx);
    overlay->AddActor(actor);
  }

  const int titlePx = std::max(12, options.heightPx / 40);
  auto title = cornerText(options.title.empty() ? toolpath.programName : options.title, titlePx,
                          {0.15, 0.15, 0.18});
  title->SetPosition(titlePx, options.heightPx - 2 * titlePx);
  overlay->AddActor2D(title);
  const int legendPx = std::max(10, titlePx * 3 / 4);
  auto feedLegend = cornerText("— feed", legendPx, kFeedColour);
  feedLegend->SetPosition(titlePx, titlePx / 2 + legendPx + legendPx / 2);
  auto rapidLegend = cornerText("- - rapid", legendPx, kRapidColour);
  rapidLegend->SetPosition(titlePx, titlePx / 2);
  overlay->AddActor2D(feedLegend);
  overlay->AddActor2D(rapidLegend);

  frame(scene->GetActiveCamera(), view, extent,
        static_cast<double>(options.widthPx) / static_cast<double>(options.heightPx));

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetNumberOfLayers(2);
  window->SetSize(options.widthPx, options.heightPx);
  window->SetMultiSamples(0);  // FXAA instead: MSAA buffers are slow under llvmpipe
  window->AddRenderer(scene);
  window->AddRenderer(overlay);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  // Encoded in memory and written here, so a bad path gives our message, not VTK's
  // ("Ran out of disk space") on stderr.
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (bytes == nullptr || bytes->GetNumberOfValues() == 0) {
    throw std::runtime_error("cannot encode the part image as PNG");
  }
  std::ofstream out(png, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes->GetPointer(0)),
            static_cast<std::streamsize>(bytes->GetNumberOfValues()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + png.string());
}

}  // namespace lathesim::render
