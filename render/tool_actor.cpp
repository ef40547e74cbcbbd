#include "render/tool_actor.hpp"

#include "render/picture_frame.hpp"

#include <array>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace lathesim::render {
namespace {

constexpr std::array<double, 3> kEdgeColour{0.08, 0.08, 0.10};
constexpr double kInsertOverHolder = 1.6;  // the insert's thickness over the holder's

/// The outline (at `position`) extruded from y = yLow to yHigh: two caps and the sides.
vtkSmartPointer<vtkPolyData> slab(const std::vector<RZ>& outline, const RZ& position, double yLow, double yHigh) {
  vtkNew<vtkPoints> points;
  for (double y : {yLow, yHigh})
    for (const RZ& p : outline) points->InsertNextPoint(position.x() + p.x(), y, position.y() + p.y());
  const auto n = static_cast<vtkIdType>(outline.size());
  vtkNew<vtkCellArray> faces;
  std::vector<vtkIdType> back, front;
  for (vtkIdType i = 0; i < n; ++i) back.push_back(n - 1 - i), front.push_back(n + i);
  faces->InsertNextCell(n, back.data());
  faces->InsertNextCell(n, front.data());
  for (vtkIdType i = 0; i < n; ++i) {
    const vtkIdType j = (i + 1) % n;
    const vtkIdType side[4] = {i, j, n + j, n + i};
    faces->InsertNextCell(4, side);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(faces);
  return polyData;
}

vtkSmartPointer<vtkActor> slabActor(const std::vector<RZ>& outline, const RZ& position, double yLow, double yHigh,
                                    const std::array<double, 3>& colour) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(slab(outline, position, yLow, yHigh));
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* p = actor->GetProperty();
  p->SetInterpolationToFlat();
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetAmbient(0.45);  // flat faces square to the light would otherwise look black or washed out
  p->SetDiffuse(0.60);
  p->SetSpecular(0.10);
  p->EdgeVisibilityOn();
  p->SetEdgeColor(kEdgeColour[0], kEdgeColour[1], kEdgeColour[2]);
  p->SetLineWidth(1.5);
  return actor;
}

}  // namespace

std::vector<vtkSmartPointer<vtkActor>> toolActors(const ToolPicture& tool, double thinMm) {
  // The viewer looks from +y (picture_frame.hpp): behind the plane is y < 0.
  const bool realSize = tool.holderHeightMm > 0 && tool.insertThicknessMm > 0;
  const double holderLow = realSize ? -tool.holderHeightMm : -thinMm / 2, holderHigh = realSize ? 0.0 : thinMm / 2;
  const double insertLow = realSize ? -tool.insertThicknessMm : -kInsertOverHolder * thinMm / 2;
  const double insertHigh = realSize ? kRakeFaceProudMm : kInsertOverHolder * thinMm / 2;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  if (tool.holder.size() >= 3) actors.push_back(slabActor(tool.holder, tool.position, holderLow, holderHigh, kHolderColour));
  if (tool.insert.size() >= 3) actors.push_back(slabActor(tool.insert, tool.position, insertLow, insertHigh, kInsertColour));
  return actors;
}

std::vector<Eigen::Vector3d> toolCorners(const ToolPicture& tool, const RZ& position) {
  std::vector<Eigen::Vector3d> corners;
  const auto add = [&](const std::vector<RZ>& outline, double behindMm) {
    for (const RZ& p : outline) {
      corners.push_back(meridianPoint(position + p));
      if (behindMm > 0) corners.push_back(meridianPoint(position + p) - Eigen::Vector3d(0, behindMm, 0));
    }
  };
  const bool realSize = tool.holderHeightMm > 0 && tool.insertThicknessMm > 0;  // as toolActors draws them
  add(tool.insert, realSize ? tool.insertThicknessMm : 0.0);
  add(tool.holder, realSize ? tool.holderHeightMm : 0.0);
  return corners;
}

}  // namespace lathesim::render
