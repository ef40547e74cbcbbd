#include "render/deviation_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include "render/offscreen_display.hpp"
#include "render/scene_export.hpp"
#include "render/vtk_scene.hpp"

namespace lathesim::render {
namespace {

constexpr std::array<double, 3> kInk{0.12, 0.12, 0.15};
constexpr std::array<double, 3> kPartLine{0.05, 0.25, 0.95};
constexpr double kPaleExcess[3] = {1.00, 0.72, 0.45};  // just beyond the tolerance
constexpr double kPaleGouge[3] = {0.55, 0.78, 1.00};
constexpr int kTableSize = 256;
constexpr double kPartViewportTop = 0.88;   // the titles live above
constexpr double kBarViewportShare = 0.26;  // the right-hand strip the colour bar lives in

std::array<double, 3> mix(const double (&a)[3], const double (&b)[3], double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

/// Blue beyond −tolerance (darker the deeper), green within, red beyond +tolerance.
vtkSmartPointer<vtkLookupTable> deviationColours(double toleranceMm, double rangeMm) {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(kTableSize);
  table->SetTableRange(-rangeMm, rangeMm);
  for (int i = 0; i < kTableSize; ++i) {
    const double value = -rangeMm + (i + 0.5) * 2 * rangeMm / kTableSize;
    const double beyond = std::clamp((std::abs(value) - toleranceMm) / std::max(rangeMm - toleranceMm, 1e-9), 0.0, 1.0);
    std::array<double, 3> c{kWithinRgb[0], kWithinRgb[1], kWithinRgb[2]};
    if (value > toleranceMm) c = mix(kPaleExcess, kExcessRgb, beyond);
    if (value < -toleranceMm) c = mix(kPaleGouge, kGougeRgb, beyond);
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  table->SetAnnotation(vtkVariant(0.0), "within tolerance");
  table->SetAnnotation(vtkVariant(0.75 * rangeMm), "excess");
  table->SetAnnotation(vtkVariant(-0.75 * rangeMm), "gouge");
  return table;
}

void styleText(vtkTextProperty* p, int fontPx, const std::array<double, 3>& colour) {
  p->SetFontSize(fontPx);
  p->SetFontFamilyToArial();
  p->SetColor(colour[0], colour[1], colour[2]);
  p->ShadowOff();
}

vtkNew<vtkRenderWindow> offscreenWindow(int widthPx, int heightPx) {
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(widthPx, heightPx);
  window->SetMultiSamples(0);
  return window;
}

/// Lines (r, z) → (Z, r, 0) as one polydata.
vtkSmartPointer<vtkPolyData> sectionLines(const std::vector<Segment>& segments) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const Segment& s : segments) {
    const vtkIdType ids[2] = {points->InsertNextPoint(s.a.y(), s.a.x(), 0.0), points->InsertNextPoint(s.b.y(), s.b.x(), 0.0)};
    lines->InsertNextCell(2, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

/// Squares of side `sizeMm` centred on `centres`, in one colour, at depth `depth`.
vtkSmartPointer<vtkActor> squares(const std::vector<RZ>& centres, double sizeMm, const double (&rgb)[3], double depth) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  const double h = sizeMm / 2;
  for (const RZ& c : centres) {
    const double r0 = std::max(0.0, c.x() - h);  // the half-section stops at the axis
    const vtkIdType ids[4] = {points->InsertNextPoint(c.y() - h, r0, depth), points->InsertNextPoint(c.y() + h, r0, depth),
                              points->InsertNextPoint(c.y() + h, c.x() + h, depth),
                              points->InsertNextPoint(c.y() - h, c.x() + h, depth)};
    quads->InsertNextCell(4, ids);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetPolys(quads);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  return actor;
}

vtkSmartPointer<vtkActor> lineActor(const std::vector<Segment>& segments, const std::array<double, 3>& rgb,
                                    double widthPx, double depth) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(sectionLines(segments));
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(0, 0, depth);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(widthPx));
  return actor;
}

}  // namespace

RgbImage deviationImage(const TriangleMesh& part, const std::vector<float>& deviationMm,
                        const DeviationImageOptions& options) {
  if (deviationMm.size() != part.vertices.size())
    throw std::runtime_error("deviation image: " + std::to_string(deviationMm.size()) + " deviations for " +
                             std::to_string(part.vertices.size()) + " vertices");
  ensureDisplay();
  double largest = 0;
  for (float d : deviationMm) largest = std::max(largest, static_cast<double>(std::abs(d)));
  const double rangeMm = std::max({largest, 2 * options.toleranceMm, 1e-3});
  const auto colours = deviationColours(options.toleranceMm, rangeMm);

  const View view = partView();
  Extent extent;
  for (const Eigen::Vector3f& v : part.vertices) extent.include(view, v.cast<double>());
  if (extent.empty()) extent.include(view, Eigen::Vector3d::Zero());

  vtkNew<vtkRenderer> paper;  // white under the titles and the colour bar
  paper->SetBackground(1, 1, 1);
  paper->InteractiveOff();
  vtkNew<vtkRenderer> scene;
  scene->SetViewport(0, 0, 1 - kBarViewportShare, kPartViewportTop);
  scene->SetBackground(1, 1, 1);
  scene->UseFXAAOn();
  vtkNew<vtkLightKit> lights;
  lights->AddLightsToRenderer(scene);
  if (!part.triangles.empty()) {
    auto data = toPolyData(part);
    vtkNew<vtkFloatArray> values;
    values->SetName("deviation_mm");
    values->SetNumberOfValues(static_cast<vtkIdType>(deviationMm.size()));
    for (std::size_t i = 0; i < deviationMm.size(); ++i) values->SetValue(static_cast<vtkIdType>(i), deviationMm[i]);
    data->GetPointData()->SetScalars(values);
    const auto mapper = shadedMapper(data);
    mapper->SetLookupTable(colours);
    mapper->SetScalarRange(-rangeMm, rangeMm);
    mapper->SetScalarModeToUsePointData();
    mapper->InterpolateScalarsBeforeMappingOn();  // a sharp edge at ±tolerance, not a blend
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetAmbient(0.45);
    actor->GetProperty()->SetDiffuse(0.6);
    actor->GetProperty()->SetSpecular(0.05);
    scene->AddActor(actor);
  }
  frame(scene->GetActiveCamera(), view, extent,
        (1 - kBarViewportShare) * options.widthPx / (kPartViewportTop * options.heightPx));

  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  const int titlePx = std::max(12, options.heightPx / 40);
  auto title = cornerText(options.title, titlePx, kInk);
  title->SetPosition(titlePx, options.heightPx - 2 * titlePx);
  overlay->AddActor2D(title);
  auto caption = cornerText(options.caption, titlePx * 3 / 4, kInk);
  caption->SetPosition(titlePx, options.heightPx - 3 * titlePx - titlePx / 2);
  overlay->AddActor2D(caption);

  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle("deviation, mm");
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%+.2f");
  bar->DrawAnnotationsOn();
  bar->SetAnnotationTextScaling(false);
  bar->SetMaximumNumberOfColors(kTableSize);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  // The annotations (gouge, within tolerance, excess) are drawn left of the bar, in the strip.
  bar->GetPositionCoordinate()->SetValue(1 - kBarViewportShare + 0.13, 0.08);
  bar->SetWidth(kBarViewportShare - 0.14);
  bar->SetHeight(0.78);
  bar->SetBarRatio(0.25);
  bar->UnconstrainedFontSizeOn();
  styleText(bar->GetTitleTextProperty(), titlePx * 3 / 4, kInk);
  styleText(bar->GetLabelTextProperty(), titlePx * 2 / 3, kInk);
  styleText(bar->GetAnnotationTextProperty(), titlePx * 2 / 3, kInk);
  bar->GetAnnotationTextProperty()->BoldOn();
  overlay->AddActor2D(bar);

  auto window = offscreenWindow(options.widthPx, options.heightPx);
  window->SetNumberOfLayers(2);
  window->AddRenderer(paper);
  window->AddRenderer(scene);
  window->AddRenderer(overlay);
  return windowImage(window);
}

void writeDeviationImagePng(const TriangleMesh& part, const std::vector<float>& deviationMm,
                            const DeviationImageOptions& options, const std::filesystem::path& png) {
  writeFileBytes(encodePng(deviationImage(part, deviationMm, options)), png);
}

SectionFrame sectionFrame(const SectionImage& image) {
  RZ lower(0, std::numeric_limits<double>::infinity()), upper(0, -std::numeric_limits<double>::infinity());
  auto include = [&](const RZ& p) { lower = lower.cwiseMin(p), upper = upper.cwiseMax(p); };
  for (const auto* segments : {&image.drawing, &image.part})
    for (const Segment& s : *segments) include(s.a), include(s.b);
  for (const auto* cells : {&image.excessCells, &image.gougeCells})
    for (const RZ& c : *cells) include(c);
  if (!(lower.y() <= upper.y())) lower = upper = RZ(0, 0);
  SectionFrame f;
  f.widthPx = image.widthPx;
  f.heightPx = image.heightPx;
  // Room around the profile for the labels above it and the legend below the axis.
  const double spanZ = std::max(upper.y() - lower.y(), 1e-3), spanR = std::max(upper.x(), 1e-3);
  f.pxPerMm = std::min(0.86 * image.widthPx / spanZ, 0.62 * image.heightPx / spanR);
  f.centre = RZ(spanR / 2 + 0.04 * image.heightPx / f.pxPerMm, (lower.y() + upper.y()) / 2);
  return f;
}

std::vector<LabelBox> sectionLabelBoxes(const SectionImage& image, const SectionFrame& frame) {
  // A grid of slots the labels' size, from the top row down: each label takes the free slot
  // nearest above-left of its point, preferring higher rows (away from the profile).
  const double width = 0.24 * image.widthPx, height = 0.075 * image.heightPx, gap = 0.01 * image.heightPx;
  const int columns = static_cast<int>(image.widthPx / width);
  const double top = 0.80 * image.heightPx + height, bottom = 0.06 * image.heightPx;
  const int rows = static_cast<int>((top - bottom) / (height + gap));
  std::vector<bool> taken(static_cast<std::size_t>(rows * columns), false);
  std::vector<LabelBox> boxes;
  for (const SectionLabel& label : image.labels) {
    const Eigen::Vector2d at = frame.pixelOf(label.at);
    int best = -1;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int row = 0; row < rows; ++row)
      for (int column = 0; column < columns; ++column) {
        if (taken[static_cast<std::size_t>(row * columns + column)]) continue;
        const double left = column * width + (image.widthPx - columns * width) / 2;
        // Horizontal distance to the point counts most; then the row, higher first.
        const double cost = std::abs(left + width / 2 - at.x()) + row * height;
        if (cost < bestCost) bestCost = cost, best = row * columns + column;
      }
    if (best < 0) break;
    taken[static_cast<std::size_t>(best)] = true;
    const int row = best / columns, column = best % columns;
    const double left = column * width + (image.widthPx - columns * width) / 2;
    const double boxTop = top - row * (height + gap);
    boxes.push_back({left, boxTop - height, left + width, boxTop});
  }
  return boxes;
}

void writeSectionImagePng(const SectionImage& image, const std::filesystem::path& png) {
  ensureDisplay();
  const SectionFrame f = sectionFrame(image);
  vtkNew<vtkRenderer> scene;
  scene->SetBackground(1, 1, 1);
  // Depths: fills at 0, the part's line above them, the drawing's line on top.
  scene->AddActor(squares(image.excessCells, image.cellMm, kExcessRgb, 0.0));
  scene->AddActor(squares(image.gougeCells, image.cellMm, kGougeRgb, 0.0));
  const double zLeft = f.centre.y() - f.widthPx / 2.0 / f.pxPerMm, zRight = f.centre.y() + f.widthPx / 2.0 / f.pxPerMm;
  scene->AddActor(lineActor({{RZ(0, zLeft), RZ(0, zRight)}}, {0.55, 0.55, 0.55}, 1.0, 0.5));  // the axis
  scene->AddActor(lineActor(image.part, kPartLine, 4.0, 1.0));
  scene->AddActor(lineActor(image.drawing, kInk, 1.5, 2.0));

  vtkCamera* camera = scene->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(f.centre.y(), f.centre.x(), 0);
  camera->SetPosition(f.centre.y(), f.centre.x(), 100);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(f.heightPx / 2.0 / f.pxPerMm);
  camera->SetClippingRange(1, 200);

  const int titlePx = std::max(12, image.heightPx / 34);
  auto title = cornerText(image.title, titlePx, kInk);
  title->SetPosition(titlePx, image.heightPx - 2 * titlePx);
  scene->AddActor2D(title);
  const int legendPx = titlePx * 3 / 4;
  const std::array<std::pair<const char*, std::array<double, 3>>, 4> legend{{
      {"— drawing", kInk}, {"— simulated part", kPartLine},
      {"excess: material outside the drawing", {kExcessRgb[0], kExcessRgb[1], kExcessRgb[2]}},
      {"gouge: material missing inside it", {kGougeRgb[0], kGougeRgb[1], kGougeRgb[2]}}}};
  if (!image.caption.empty()) {
    auto caption = cornerText(image.caption, legendPx, kInk);
    caption->SetPosition(titlePx, image.heightPx - 3 * titlePx - legendPx / 2);
    scene->AddActor2D(caption);
  }
  // Z at the drawing's corners, under the axis.
  std::vector<double> ticks;
  for (const Segment& s : image.drawing)
    for (double z : {s.a.y(), s.b.y()})
      if (std::none_of(ticks.begin(), ticks.end(), [&](double t) { return std::abs(t - z) * f.pxPerMm < 4.0 * legendPx; }))
        ticks.push_back(z);
  for (double z : ticks) {
    char text[32];
    std::snprintf(text, sizeof text, "Z%g", std::round(z * 1000) / 1000);
    auto tick = cornerText(text, legendPx, {0.4, 0.4, 0.4});
    tick->GetTextProperty()->SetJustificationToCentered();
    const Eigen::Vector2d at = f.pixelOf(RZ(0, z));
    tick->SetPosition(at.x(), at.y() - 1.6 * legendPx);
    scene->AddActor2D(tick);
  }
  for (std::size_t n = 0; n < legend.size(); ++n) {
    auto entry = cornerText(legend[n].first, legendPx, legend[n].second);
    entry->SetPosition(titlePx + static_cast<int>(n) * image.widthPx / 4, legendPx / 2);
    scene->AddActor2D(entry);
  }

  // Labels stand in boxes that do not overlap (sectionLabelBoxes), a leader to their point.
  const std::vector<LabelBox> boxes = sectionLabelBoxes(image, f);
  for (std::size_t n = 0; n < boxes.size(); ++n) {
    const SectionLabel& label = image.labels[n];
    vtkNew<vtkCaptionActor2D> caption;
    caption->SetCaption(label.text.c_str());
    caption->SetAttachmentPoint(label.at.y(), label.at.x(), 3.0);
    caption->BorderOff();
    caption->LeaderOn();
    caption->ThreeDimensionalLeaderOff();
    caption->GetCaptionTextProperty()->SetFontSize(legendPx);
    styleText(caption->GetCaptionTextProperty(), legendPx, label.gouge ? std::array<double, 3>{kGougeRgb[0], kGougeRgb[1], kGougeRgb[2]}
                                                                       : std::array<double, 3>{kExcessRgb[0], kExcessRgb[1], kExcessRgb[2]});
    caption->GetCaptionTextProperty()->BoldOn();
    caption->GetCaptionTextProperty()->SetJustificationToLeft();
    caption->GetProperty()->SetColor(kInk[0], kInk[1], kInk[2]);
    caption->GetProperty()->SetLineWidth(1.5);
    const Eigen::Vector2d at = f.pixelOf(label.at);
    caption->SetPosition(boxes[n].left - at.x(), boxes[n].bottom - at.y());
    caption->SetWidth((boxes[n].right - boxes[n].left) / image.widthPx);
    caption->SetHeight((boxes[n].top - boxes[n].bottom) / image.heightPx);
    caption->GetTextActor()->SetTextScaleModeToNone();
    scene->AddActor2D(caption);
  }

  auto window = offscreenWindow(image.widthPx, image.heightPx);
  window->AddRenderer(scene);
  writeWindowPng(window, png);
}

}  // namespace lathesim::render
