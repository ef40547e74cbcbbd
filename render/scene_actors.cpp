#include "render/scene_actors.hpp"

#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include "geometry/revolved_mesh.hpp"
#include "render/machine_meshes.hpp"
#include "render/vtk_scene.hpp"

namespace lathesim::render {
namespace {

constexpr int kRoundSteps = 96;  // facets around the ghost and the chuck body

/// A rectangle of the meridian plane [r0, r1] × [z0, z1] turned about the axis (r0 = 0: a
/// cylinder, else a tube).
TriangleMesh revolvedRectangle(double r0, double r1, double z0, double z1) {
  // The material on the right (revolved_mesh.hpp): down the outside, up the inside.
  std::vector<RZ> loop{{r1, z1}, {r1, z0}, {r0, z0}, {r0, z1}, {r1, z1}};
  if (r0 <= 0) loop = {{0, z1}, {r1, z1}, {r1, z0}, {0, z0}};
  return revolvedMesh({loop}, kRoundSteps);
}

vtkSmartPointer<vtkActor> flatActor(vtkPolyData* data, const Rgb& colour) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  return actor;
}

vtkSmartPointer<vtkActor> steelActor(vtkPolyData* data, bool keepBelowAxis, const Rgb& colour) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  if (keepBelowAxis) mapper->AddClippingPlane(belowAxisPlane());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* p = actor->GetProperty();
  p->SetInterpolationToFlat();
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetAmbient(0.5);
  p->SetDiffuse(0.6);
  p->SetSpecular(0.15);
  return actor;
}

/// Rectangles [r0, r1] × [z0, z1] of the meridian plane as quads at y = 0.
class Quads {
 public:
  void add(double r0, double r1, double z0, double z1) {
    const vtkIdType first = points_->GetNumberOfPoints();
    points_->InsertNextPoint(r0, 0, z0);
    points_->InsertNextPoint(r1, 0, z0);
    points_->InsertNextPoint(r1, 0, z1);
    points_->InsertNextPoint(r0, 0, z1);
    const vtkIdType ids[4] = {first, first + 1, first + 2, first + 3};
    polys_->InsertNextCell(4, ids);
  }
  vtkSmartPointer<vtkPolyData> data() const {
    auto d = vtkSmartPointer<vtkPolyData>::New();
    d->SetPoints(points_);
    d->SetPolys(polys_);
    return d;
  }

 private:
  vtkNew<vtkPoints> points_;
  vtkNew<vtkCellArray> polys_;
};

}  // namespace

vtkSmartPointer<vtkPlane> belowAxisPlane() {
  auto plane = vtkSmartPointer<vtkPlane>::New();
  plane->SetOrigin(0, 0, 0);
  plane->SetNormal(-1, 0, 0);  // VTK keeps the side the normal points to
  return plane;
}

vtkSmartPointer<vtkActor> ghostActor(const BarOutline& bar) {
  const auto data = toPolyData(revolvedRectangle(bar.boreRadiusMm, bar.radiusMm, bar.zLowMm, bar.zHighMm));
  auto actor = flatActor(data, kGhostColour);
  actor->GetProperty()->SetOpacity(kGhostOpacity);
  actor->GetProperty()->FrontfaceCullingOn();
  return actor;
}

std::vector<vtkSmartPointer<vtkActor>> chuckActors(const ChuckPicture& chuck, bool keepBelowAxis) {
  std::vector<vtkSmartPointer<vtkActor>> actors;
  actors.push_back(steelActor(toPolyData(jawsMesh(chuck)), keepBelowAxis, kJawColour));
  const auto body = toPolyData(revolvedRectangle(0, chuck.jawOuterRadiusMm, chuck.bodyZLowMm, chuck.jawZLowMm));
  actors.push_back(steelActor(body, keepBelowAxis, kChuckColour));
  return actors;
}

vtkSmartPointer<vtkActor> tailstockActor(const TailstockPicture& tailstock) {
  return steelActor(toPolyData(tailstockMesh(tailstock)), false, kTailstockColour);
}

vtkSmartPointer<vtkActor> partCutActor(const SampledSection& section) {
  // Each row of samples at one z: the runs inside the material, as squares of the step's size
  // (the profile drawn over them smooths their edges).
  Quads quads;
  const double h = section.stepMm;
  for (int k = 0; k < section.zCount; ++k) {
    const double z = section.zFirstMm + k * h;
    for (int i = 0; i < section.rCount;) {
      if (!(section.at(i, k) < 0)) {
        ++i;
        continue;
      }
      const int first = i;
      while (i < section.rCount && section.at(i, k) < 0) ++i;
      quads.add(std::max(0.0, (first - 0.5) * h), (i - 0.5) * h, z - h / 2, z + h / 2);
    }
  }
  return flatActor(quads.data(), kCutFaceColour);
}

std::vector<vtkSmartPointer<vtkActor>> chuckCutActors(const ChuckPicture& chuck) {
  Quads jaw, body;
  jaw.add(chuck.jawInnerRadiusMm, chuck.jawOuterRadiusMm, chuck.jawZLowMm, chuck.jawZHighMm);
  body.add(0, chuck.jawOuterRadiusMm, chuck.bodyZLowMm, chuck.jawZLowMm);
  return {flatActor(jaw.data(), kJawColour), flatActor(body.data(), kChuckColour)};
}

}  // namespace lathesim::render
