#include "render/overlay_2d.hpp"

#include <algorithm>
#include <cmath>

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkUnsignedCharArray.h>

namespace lathesim::render {

void Overlay2D::line(const Pixel& a, const Pixel& b, const Rgb& colour) {
  const int first = static_cast<int>(points_.size());
  points_.push_back(a);
  points_.push_back(b);
  lines_.push_back({first, first + 1});
  lineColours_.push_back(colour);
}

double Overlay2D::dashed(const Pixel& a, const Pixel& b, const Rgb& colour, double dashPx, double phasePx) {
  const double length = (b - a).norm();
  const double period = 1.5 * dashPx;
  if (length == 0.0 || dashPx <= 0.0) return phasePx;
  const Eigen::Vector2d unit = (b - a) / length;
  // s runs along the line; the pattern starts `phasePx` into a period at a.
  for (double start = -std::fmod(phasePx, period); start < length; start += period) {
    const double s0 = std::max(start, 0.0), s1 = std::min(start + dashPx, length);
    if (s1 > s0) line(a + unit * s0, a + unit * s1, colour);
  }
  return std::fmod(phasePx + length, period);
}

void Overlay2D::polygon(const std::vector<Pixel>& corners, const Rgb& colour) {
  std::vector<int> ids;
  for (const Pixel& c : corners) {
    ids.push_back(static_cast<int>(points_.size()));
    points_.push_back(c);
  }
  polygons_.push_back(std::move(ids));
  polygonColours_.push_back(colour);
}

void Overlay2D::arrowhead(const Pixel& tip, const Eigen::Vector2d& direction, double lengthPx, const Rgb& colour) {
  const double norm = direction.norm();
  if (norm == 0.0) return;
  const Eigen::Vector2d along = direction / norm, across(-along.y(), along.x());
  const Pixel base = tip - along * lengthPx;
  polygon({tip, base + across * (0.4 * lengthPx), base - across * (0.4 * lengthPx)}, colour);
}

vtkSmartPointer<vtkActor2D> Overlay2D::actor(double lineWidthPx) const {
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(static_cast<vtkIdType>(points_.size()));
  for (std::size_t i = 0; i < points_.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), points_[i].x(), points_[i].y(), 0.0);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  auto addColour = [&](const Rgb& c) { colours->InsertNextTuple3(255.0 * c[0], 255.0 * c[1], 255.0 * c[2]); };
  vtkNew<vtkCellArray> lines, polys;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const vtkIdType ids[2] = {lines_[i][0], lines_[i][1]};
    lines->InsertNextCell(2, ids);
    addColour(lineColours_[i]);
  }
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    std::vector<vtkIdType> ids(polygons_[i].begin(), polygons_[i].end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    addColour(polygonColours_[i]);
  }
  // VTK numbers cells lines first, then polygons: the colours above are in that order.
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  data->SetPolys(polys);
  data->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(data);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(static_cast<float>(lineWidthPx));
  return actor;
}

std::optional<ClipSpan> clipToRectangle(const Pixel& a, const Pixel& b, double x0, double y0, double x1, double y1) {
  const Eigen::Vector2d d = b - a;
  ClipSpan span;
  // Each side: p·t ≤ q keeps the point a + t·d inside.
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - x0, x1 - a.x(), a.y() - y0, y1 - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return std::nullopt;  // parallel to this side and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) span.t0 = std::max(span.t0, t);
    else span.t1 = std::min(span.t1, t);
  }
  if (span.t0 > span.t1) return std::nullopt;
  return span;
}

}  // namespace lathesim::render
