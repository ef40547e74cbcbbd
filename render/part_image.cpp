#include "render/part_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkUnsignedCharArray.h>

#include "render/move_points.hpp"
#include "render/offscreen_display.hpp"
#include "render/vtk_scene.hpp"
#include "render/tool_actor.hpp"

namespace lathesim::render {
namespace {

// Colours (RGB 0–1). The test relies on feeds being clearly blue and rapids clearly red.
constexpr std::array<double, 3> kFeedColour{0.05, 0.25, 0.95};
constexpr std::array<double, 3> kRapidColour{0.90, 0.08, 0.08};
constexpr std::array<double, 3> kThreadColour{0.05, 0.55, 0.15};
constexpr std::array<double, 3> kMetalColour{0.74, 0.76, 0.79};
constexpr double kLineWidthPx = 2.0;
// The tool's slabs are this thick, as a fraction of the picture's diagonal (mm): enough to
// read as solid, thin enough to stay in the meridian plane.
constexpr double kToolThicknessPerSize = 0.012;

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
      const auto& colour = move.kind == interp::MoveKind::Thread ? kThreadColour : kFeedColour;
      for (std::size_t i = 1; i < drawn.size(); ++i) addSegment(drawn[i - 1], drawn[i], colour);
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

  // A close-up looks straight at the side, so that a thread's profile shows true on the
  // silhouette; the whole part is seen turned a little, its end face showing.
  const View view = options.closeUp ? partView(0.0) : partView();
  Extent extent;
  if (options.closeUp) {
    const CloseUp& box = *options.closeUp;
    for (const double z : {box.zLowMm, box.zHighMm})
      for (const double r : {box.radiusLowMm, box.radiusHighMm}) extent.include(view, Eigen::Vector3d(r, 0.0, z));
    // The whole part in depth, so that the camera does not clip it open.
    for (const Eigen::Vector3f& v : part.vertices) {
      const double depth = v.cast<double>().dot(view.towardsViewer);
      extent.minDepth = std::min(extent.minDepth, depth);
      extent.maxDepth = std::max(extent.maxDepth, depth);
    }
  } else {
    for (const Eigen::Vector3f& v : part.vertices) extent.include(view, v.cast<double>());
    for (const interp::Move& m : toolpath.moves)
      for (const RZ& p : movePoints(m)) extent.include(view, Eigen::Vector3d(p.x(), 0.0, p.y()));
  }
  // The insert is framed; a long holder shank may run out of the picture.
  if (options.tool && !options.closeUp) {
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
    const auto data = toPolyData(part);
    const auto mapper = shadedMapper(data);
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

  if (options.tool && !options.closeUp) {
    for (const auto& actor : toolActors(*options.tool, std::max(sizeMm * kToolThicknessPerSize, 0.2)))
      scene->AddActor(actor);
  }

  // The toolpath lies in the part's meridian plane, mostly inside or on the part; it is drawn
  // in a second layer with the same camera and a fresh depth buffer, so it is always on top.
  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  overlay->SetActiveCamera(scene->GetActiveCamera());
  if (!toolpath.moves.empty() && !options.closeUp) {
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
  if (!options.closeUp) {
    // Bottom up: rapid, feed, and thread when the program has thread moves.
    std::vector<std::pair<std::string, std::array<double, 3>>> legend{{"- - rapid", kRapidColour}, {"— feed", kFeedColour}};
    if (std::any_of(toolpath.moves.begin(), toolpath.moves.end(),
                    [](const interp::Move& m) { return m.kind == interp::MoveKind::Thread; }))
      legend.push_back({"— thread", kThreadColour});
    for (std::size_t n = 0; n < legend.size(); ++n) {
      auto text = cornerText(legend[n].first, legendPx, legend[n].second);
      text->SetPosition(titlePx, titlePx / 2 + static_cast<int>(n) * (legendPx + legendPx / 2));
      overlay->AddActor2D(text);
    }
  }

  frame(scene->GetActiveCamera(), view, extent,
        static_cast<double>(options.widthPx) / static_cast<double>(options.heightPx));

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetNumberOfLayers(2);
  window->SetSize(options.widthPx, options.heightPx);
  window->SetMultiSamples(0);  // FXAA instead: MSAA buffers are slow under llvmpipe
  window->AddRenderer(scene);
  window->AddRenderer(overlay);

  writeWindowPng(window, png);
}

}  // namespace lathesim::render
