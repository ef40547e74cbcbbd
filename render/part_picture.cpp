#include "render/part_picture.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include "render/move_points.hpp"
#include "render/offscreen_display.hpp"
#include "render/label_layout.hpp"
#include "render/machine_meshes.hpp"
#include "render/picture_annotations.hpp"
#include "render/scene_actors.hpp"
#include "render/tool_actor.hpp"
#include "render/vtk_scene.hpp"

namespace lathesim::render {
namespace {

constexpr double kMarginFraction = 0.06;  // of the picture, free on each side
constexpr double kDimensionBand = 0.15;   // of the height, kept free above for length dimensions
constexpr double kToolNearFraction = 0.25;  // a tool this far (of the frame's size) off it is framed too
// The tool's slabs are this thick, as a fraction of the picture's diagonal (mm): enough to
// read as solid, thin enough to stay in the meridian plane.
constexpr double kToolThicknessPerSize = 0.012;
constexpr double kCloseUpFeatureAngleDeg = 50.0;  // see setPart
// The jaws' front ends framed with a bar: this far behind their face (of the bar's length)
// and out past the bar (of its radius).
constexpr double kJawFramedOfBarLength = 0.2;
constexpr double kJawFramedOfBarRadius = 0.25;

View viewOf(PartView view) { return partView(view == PartView::Iso ? kIsoAzimuthDeg : 0.0); }

void includeCircle(Extent& e, const View& view, double radius, double z) {
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * M_PI * k / 64;
    e.include(view, Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), z));
  }
}

/// The picture frames the bar and the jaws (see part_image.hpp), and the tool when near.
PictureFrame framePicture(const PartImageOptions& options, const interp::Toolpath& toolpath, const TriangleMesh& part) {
  const View view = viewOf(options.view);
  Extent e;
  if (options.closeUp) {
    const CloseUp& box = *options.closeUp;
    for (const double z : {box.zLowMm, box.zHighMm})
      for (const double r : {box.radiusLowMm, box.radiusHighMm}) e.include(view, meridianPoint(RZ(r, z)));
    // The whole part in depth, so that the camera does not clip it open.
    for (const Eigen::Vector3f& v : part.vertices) {
      const double depth = v.cast<double>().dot(view.towardsViewer);
      e.minDepth = std::min(e.minDepth, depth), e.maxDepth = std::max(e.maxDepth, depth);
    }
    return frameExtent(view, e, options.widthPx, options.heightPx, kMarginFraction);
  }
  if (options.bar) {
    for (double z : {options.bar->zLowMm, options.bar->zHighMm}) includeCircle(e, view, options.bar->radiusMm, z);
  } else if (!part.vertices.empty()) {
    for (const Eigen::Vector3f& v : part.vertices) e.include(view, v.cast<double>());
  } else {
    for (const interp::Move& m : toolpath.moves)
      for (const RZ& p : movePoints(m)) e.include(view, meridianPoint(p));
  }
  if (options.chuck) {
    const ChuckPicture& c = *options.chuck;
    const double half = kJawHalfWidthPerRadius * c.jawOuterRadiusMm;
    // With a bar, only the jaws' front ends are framed: the rest of them runs out of the
    // picture, as the body does, and the part stays large.
    double zLow = c.jawZLowMm, rHigh = c.jawOuterRadiusMm;
    if (options.bar) {
      zLow = std::max(zLow, c.jawZHighMm - kJawFramedOfBarLength * (options.bar->zHighMm - options.bar->zLowMm));
      rHigh = std::min(rHigh, std::max(c.jawInnerRadiusMm, options.bar->radiusMm) +
                                  kJawFramedOfBarRadius * options.bar->radiusMm);
    }
    for (int jaw = 0; jaw < 3; ++jaw) {
      const double a = jaw * 2 * M_PI / 3;
      const Eigen::Vector3d out(std::cos(a), std::sin(a), 0), side(-std::sin(a), std::cos(a), 0);
      for (double z : {zLow, c.jawZHighMm})
        for (double r : {c.jawInnerRadiusMm, rHigh})
          for (double s : {-half, half}) e.include(view, out * r + side * s + Eigen::Vector3d(0, 0, z));
    }
  }
  if (options.tailstock) {  // its point and cone; the quill runs out of the picture
    const TailstockPicture& t = *options.tailstock;
    e.include(view, Eigen::Vector3d(0, 0, t.pointZMm));
    includeCircle(e, view, t.quillRadiusMm, t.coneEndZMm());
  }
  if (e.empty()) e.include(view, Eigen::Vector3d::Zero());
  if (options.tool && !options.tool->insert.empty()) {  // the tool near: it and its holder, whole
    Extent insert;
    for (const RZ& p : options.tool->insert) insert.include(view, meridianPoint(options.tool->position + p));
    const double nearMm = kToolNearFraction * std::max(e.maxRight - e.minRight, e.maxUp - e.minUp);
    const bool near = insert.minRight < e.maxRight + nearMm && insert.maxRight > e.minRight - nearMm &&
                      insert.minUp < e.maxUp + nearMm && insert.maxUp > e.minUp - nearMm;
    if (near)
      for (const Eigen::Vector3d& corner : toolCorners(*options.tool, options.tool->position)) e.include(view, corner);
  }
  // The depth of everything drawn, so that the camera clips none of it (across and up, the
  // chuck's body may run out of the picture).
  Extent behind;
  if (options.chuck) includeCircle(behind, view, options.chuck->jawOuterRadiusMm, options.chuck->bodyZLowMm);
  if (options.tailstock) {
    const TailstockPicture& t = *options.tailstock;
    includeCircle(behind, view, t.quillRadiusMm, t.coneEndZMm() + t.quillLengthMm);
  }
  if (options.tool)  // its holder's back face, behind the plane
    for (const Eigen::Vector3d& corner : toolCorners(*options.tool, options.tool->position)) behind.include(view, corner);
  if (!behind.empty()) e.minDepth = std::min(e.minDepth, behind.minDepth), e.maxDepth = std::max(e.maxDepth, behind.maxDepth);
  return frameExtent(view, e, options.widthPx, options.heightPx, kMarginFraction, kDimensionBand);
}

/// The insert is inside the picture (some of it at least).
bool toolInPicture(const ToolPicture& tool, const RZ& position, const PictureFrame& frame) {
  const ClipRectangle clip = clipRectangleOf(frame);
  return std::any_of(tool.insert.begin(), tool.insert.end(),
                     [&](const RZ& p) { return clip.contains(frame.pixelOf(RZ(position + p))); });
}

/// The whole tool, insert and holder front and back, is inside the picture.
bool wholeToolInPicture(const ToolPicture& tool, const RZ& position, const PictureFrame& frame) {
  const std::vector<Eigen::Vector3d> corners = toolCorners(tool, position);
  return std::all_of(corners.begin(), corners.end(), [&](const Eigen::Vector3d& corner) {
    const Pixel p = frame.pixelOf(corner);
    return p.x() >= 0 && p.x() <= frame.widthPx && p.y() >= 0 && p.y() <= frame.heightPx;
  });
}

/// What the title block says of a tool not drawn whole inside the picture (empty: nothing).
/// `programShift`: as ToolPicture's, for the point the program names.
std::string toolNote(bool drawn, bool whole, const RZ& position, const RZ& programShift) {
  const std::string where = programPoint(position - programShift);
  if (!drawn) return "the tool is off the picture, at " + where + " (the gold arrow at the edge)";
  if (!whole) return "the tool at " + where + " runs off the picture";
  return "";
}

vtkSmartPointer<vtkTextActor> textActor(const Label& label, int fontPx) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(label.text.c_str());
  vtkTextProperty* p = actor->GetTextProperty();
  p->SetFontSize(fontPx);
  p->SetFontFamilyToArial();
  p->SetColor(label.colour[0], label.colour[1], label.colour[2]);
  if (label.justify == Justify::Centre) p->SetJustificationToCentered();
  if (label.justify == Justify::Right) p->SetJustificationToRight();
  if (label.backed) {
    p->SetBackgroundColor(1.0, 1.0, 1.0);
    p->SetBackgroundOpacity(1.0);
  }
  actor->SetPosition(label.at.x(), label.at.y());
  return actor;
}

}  // namespace

PictureFrame partPictureFrame(const PartImageOptions& options, const interp::Toolpath& toolpath, const TriangleMesh& part) {
  return framePicture(options, toolpath, part);
}

std::string_view viewName(PartView view) {
  switch (view) {
    case PartView::Iso: return "iso";
    case PartView::Front: return "front";
    case PartView::Section: return "section";
  }
  return "iso";
}

std::optional<PartView> viewNamed(std::string_view name) {
  for (PartView v : {PartView::Iso, PartView::Front, PartView::Section})
    if (viewName(v) == name) return v;
  return std::nullopt;
}

struct PartPicture::Scene {
  PartImageOptions options;
  const interp::Toolpath& toolpath;
  PictureFrame frame;
  double sizeMm = 1;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> solids;
  vtkNew<vtkRenderer> overlay;
  vtkNew<vtkActor> part;
  std::vector<vtkSmartPointer<vtkActor>> tool;
  std::vector<vtkSmartPointer<vtkProp>> annotations;  // the overlay's, rebuilt with the progress
  std::vector<PlacedLabel> labels;          // as the last show() placed them
  std::vector<PixelSegment> dimensionLines;  // and the lines they keep clear of
  std::vector<LeaderLine> leaders;          // and the leaders to the labels moved

  Scene(const PartImageOptions& o, const interp::Toolpath& t) : options(o), toolpath(t) {}
};

PartPicture::PartPicture(const PartImageOptions& options, const interp::Toolpath& toolpath,
                         const TriangleMesh& framingPart) {
  if (options.widthPx <= 0 || options.heightPx <= 0) {
    throw std::runtime_error("part image: size must be positive, not " + std::to_string(options.widthPx) + "×" +
                             std::to_string(options.heightPx));
  }
  // Before any VTK window exists: without a reachable X server VTK aborts the process.
  ensureDisplay();
  scene_ = std::make_unique<Scene>(options, toolpath);
  Scene& s = *scene_;
  s.frame = framePicture(options, toolpath, framingPart);
  s.sizeMm = std::hypot(options.widthPx, options.heightPx) / s.frame.pxPerMm;
  const bool section = options.view == PartView::Section;

  vtkRenderer* solids = s.solids;
  solids->GradientBackgroundOn();
  solids->SetBackground(0.80, 0.83, 0.87);   // bottom
  solids->SetBackground2(1.00, 1.00, 1.00);  // top
  solids->UseFXAAOn();
  vtkNew<vtkLightKit> lights;
  lights->AddLightsToRenderer(solids);

  vtkProperty* metal = s.part->GetProperty();
  metal->SetInterpolationToPhong();
  metal->SetColor(kMetalColour[0], kMetalColour[1], kMetalColour[2]);
  metal->SetAmbient(0.15);
  metal->SetDiffuse(0.75);
  metal->SetSpecular(0.45);
  metal->SetSpecularPower(40.0);
  solids->AddActor(s.part);
  if (options.bar) solids->AddActor(ghostActor(*options.bar));
  if (options.chuck) {
    for (const auto& actor : chuckActors(*options.chuck, section)) solids->AddActor(actor);
    if (section)
      for (const auto& actor : chuckCutActors(*options.chuck)) solids->AddActor(actor);
  }
  if (options.tailstock) solids->AddActor(tailstockActor(*options.tailstock));
  if (section && options.section) solids->AddActor(partCutActor(*options.section));

  s.overlay->SetLayer(1);
  s.overlay->InteractiveOff();
  applyFrame(solids->GetActiveCamera(), s.frame);

  s.window->SetOffScreenRendering(1);
  s.window->SetNumberOfLayers(2);
  s.window->SetSize(options.widthPx, options.heightPx);
  s.window->SetMultiSamples(0);  // FXAA instead: MSAA buffers are slow under llvmpipe
  s.window->AddRenderer(solids);
  s.window->AddRenderer(s.overlay);
  setPart(framingPart);
  show(std::nullopt, options.tool, options.caption);
}

PartPicture::~PartPicture() = default;

const PictureFrame& PartPicture::frame() const { return scene_->frame; }

void PartPicture::setPart(const TriangleMesh& part) {
  Scene& s = *scene_;
  s.part->SetVisibility(!part.triangles.empty());
  if (part.triangles.empty()) return;
  // A close-up magnifies the facets: neighbours on a flank that lean more than 35° against
  // each other (voxel facets do) show as a saw edge where the normals split. Its true edges
  // are sharper (a 60° thread's crest meets its flanks at 60°, its flanks meet at 120°).
  const auto mapper =
      shadedMapper(toPolyData(part), s.options.closeUp ? kCloseUpFeatureAngleDeg : kShoulderFeatureAngleDeg);
  mapper->ScalarVisibilityOff();
  if (s.options.view == PartView::Section) mapper->AddClippingPlane(belowAxisPlane());
  s.part->SetMapper(mapper);
}

void PartPicture::addCrash(const CrashMark& crash) { scene_->options.crashes.push_back(crash); }

void PartPicture::show(const std::optional<interp::ToolpathInstant>& shown, const std::optional<ToolPicture>& shownTool,
                       const std::string& caption) {
  Scene& s = *scene_;
  const PartImageOptions& o = s.options;
  for (const auto& actor : s.tool) s.solids->RemoveActor(actor);
  s.tool.clear();
  for (const auto& prop : s.annotations) s.overlay->RemoveViewProp(prop);
  s.annotations.clear();

  const ClipRectangle clip = clipRectangleOf(s.frame);
  Overlay2D thick, thin, marks;
  // The labels in the order of their claim to their place (label_layout.hpp): the title block
  // and the legend stay where they are; then crashes, dimensions, the toolpath.
  std::vector<Label> titleLabels, scaleLabels, crashLabels, dimensionLabels, pathLabels;
  std::vector<PixelSegment> dimensionLines;
  std::string toolLine;  // in the title block, when the tool is not drawn whole
  if (shownTool && !o.closeUp) {
    ToolPicture tool = *shownTool;
    if (shown) {  // where the move shown puts it, and what the program calls that point
      tool.position = shown->position;
      if (!s.toolpath.moves.empty()) {  // moves.size() once all are done: the last
        const interp::Move& move = s.toolpath.moves[std::min(shown->move, s.toolpath.moves.size() - 1)];
        tool.programShift = move.workShift + move.offsetShift;
      }
    }
    const bool drawn = toolInPicture(tool, tool.position, s.frame);
    if (drawn) {
      s.tool = toolActors(tool, std::max(s.sizeMm * kToolThicknessPerSize, 0.2));
      for (const auto& actor : s.tool) s.solids->AddActor(actor);
    } else {
      drawToolOutside(tool.position, s.frame, clip, marks);
    }
    toolLine = toolNote(drawn, wholeToolInPicture(tool, tool.position, s.frame), tool.position, tool.programShift);
  }
  const int titlePx = std::max(12, o.heightPx / 40);
  const int legendPx = std::max(10, titlePx * 3 / 4);
  const double left = titlePx;
  double lineBelow = o.heightPx - 2 * titlePx;  // the title's baseline, then each line's under it
  titleLabels.push_back({Pixel(left, lineBelow), o.title.empty() ? s.toolpath.programName : o.title, kInkColour,
                         Justify::Left, true});
  for (const std::string& line : {o.subtitle, caption, toolLine})
    if (!line.empty()) {
      lineBelow -= 1.3 * legendPx + (titleLabels.size() == 1 ? 0.4 * titlePx : 0.0);
      titleLabels.push_back({Pixel(left, lineBelow), line, kInkColour, Justify::Left, true});
    }
  const double titleBlockBottomPx = lineBelow - 0.35 * legendPx;  // below the last line's descenders

  if (o.bar) drawBarOutline(*o.bar, o.view, s.frame, thin);
  if (o.section && o.view == PartView::Section) {  // the cut's outline over the squares of the cut face
    const MeridianProfile profile = MeridianProfile::fromSection(*o.section);
    for (const Segment& seg : profile.surface()) thin.line(s.frame.pixelOf(seg.a), s.frame.pixelOf(seg.b), kInkColour);
  }
  if (!o.closeUp) drawToolpath(s.toolpath, shown, s.frame, clip, thick, marks, pathLabels);
  if (!o.dimensions.diameters.empty() || !o.dimensions.lengths.empty()) {
    const double topPx = s.frame.heightPx * (1.0 - kMarginFraction - kDimensionBand);
    drawDimensions(o.dimensions, o.dimensionDecimals, s.frame, topPx, titleBlockBottomPx, thin, marks, dimensionLabels,
                   dimensionLines);
  }
  if (o.view != PartView::Iso) drawScaleBar(s.frame, thin, scaleLabels);

  Overlay2D crashes;  // drawn last: over the toolpath and the tool
  drawCrashMarks(o.crashes, s.frame, clip, crashMarkRadiusPx(o.heightPx), crashes, crashLabels);

  // The legend, bottom up.
  std::vector<std::pair<std::string, Rgb>> legend;
  if (!o.closeUp) {
    legend = {{"- - rapid", kRapidColour}, {"— feed", kFeedColour}};
    if (std::any_of(s.toolpath.moves.begin(), s.toolpath.moves.end(),
                    [](const interp::Move& m) { return m.kind == interp::MoveKind::Thread; }))
      legend.push_back({"— thread", kThreadColour});
  }
  if (o.bar) legend.push_back({"the bar before cutting", kGhostLineColour});
  if (o.tailstock) legend.push_back({"green: the tailstock's centre", kTailstockColour});
  if (!o.crashes.empty()) legend.push_back({"red disc: a crash", kCrashColour});
  if (!o.dimensions.diameters.empty() || !o.dimensions.lengths.empty()) legend.push_back({"dimensions, mm", kDimensionColour});

  std::vector<Label> labels;
  std::vector<int> fontPx;
  const auto take = [&](const std::vector<Label>& from, int px) {
    for (const Label& l : from) labels.push_back(l), fontPx.push_back(px);
  };
  labels.push_back(titleLabels.front());
  fontPx.push_back(titlePx);
  take({titleLabels.begin() + 1, titleLabels.end()}, legendPx);
  for (std::size_t n = 0; n < legend.size(); ++n)
    take({{Pixel(left, titlePx / 2.0 + static_cast<double>(n) * 1.5 * legendPx), legend[n].first, legend[n].second,
           Justify::Left, true}},
         legendPx);
  take(scaleLabels, legendPx);
  const std::size_t fixedCount = labels.size();
  for (const auto* group : {&crashLabels, &dimensionLabels, &pathLabels}) take(*group, legendPx);
  LabelPlacement placement = placeLabels(labels, fontPx, fixedCount, dimensionLines, clip);
  for (const LeaderLine& leader : placement.leaders) thin.line(leader.segment[0], leader.segment[1], leader.colour);
  s.labels = std::move(placement.labels);
  s.leaders = std::move(placement.leaders);
  s.dimensionLines = std::move(dimensionLines);

  auto add = [&](const vtkSmartPointer<vtkProp>& prop) {
    s.overlay->AddViewProp(prop);
    s.annotations.push_back(prop);
  };
  if (!thin.empty()) add(thin.actor(1.5));
  if (!thick.empty()) add(thick.actor(2.0));
  if (!marks.empty()) add(marks.actor(1.0));
  if (!crashes.empty()) add(crashes.actor(1.0));
  for (const PlacedLabel& placed : s.labels) add(textActor(placed.label, placed.fontPx));
}

const std::vector<PlacedLabel>& PartPicture::labels() const { return scene_->labels; }
const std::vector<PixelSegment>& PartPicture::dimensionLines() const { return scene_->dimensionLines; }
const std::vector<LeaderLine>& PartPicture::leaders() const { return scene_->leaders; }

void PartPicture::writePng(const std::filesystem::path& png) { writeWindowPng(scene_->window, png); }
RgbImage PartPicture::image() { return windowImage(scene_->window); }

void PartPicture::readRgb(std::vector<unsigned char>& rgb) {
  vtkRenderWindow* window = scene_->window;
  window->Render();
  const int w = scene_->options.widthPx, h = scene_->options.heightPx;
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, w - 1, h - 1, /*front=*/0, pixels);
  rgb.resize(static_cast<std::size_t>(w) * h * 3);
  const unsigned char* source = pixels->GetPointer(0);
  for (int y = 0; y < h; ++y)  // VTK's rows run bottom up
    std::copy_n(source + static_cast<std::size_t>(h - 1 - y) * w * 3, static_cast<std::size_t>(w) * 3,
                rgb.data() + static_cast<std::size_t>(y) * w * 3);
}

}  // namespace lathesim::render
