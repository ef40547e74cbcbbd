#include "render/stl_reader.hpp"

#include <fstream>

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>

namespace lathesim::render {

StlRead readStl(const std::filesystem::path& stl) {
  if (!std::ifstream(stl, std::ios::binary)) return {std::nullopt, "cannot read the STL file"};
  vtkNew<vtkSTLReader> reader;
  const std::string name = stl.string();
  reader->SetFileName(name.c_str());
  reader->MergingOn();
  reader->GlobalWarningDisplayOff();  // a broken file is reported below, in our words
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  if (data == nullptr || data->GetNumberOfPolys() == 0)
    return {std::nullopt, "not an STL file with triangles (binary or ASCII)"};
  TriangleMesh mesh;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    mesh.vertices.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
  }
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = data->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids);) {
    if (ids->GetNumberOfIds() != 3) continue;
    mesh.triangles.push_back({static_cast<std::uint32_t>(ids->GetId(0)), static_cast<std::uint32_t>(ids->GetId(1)),
                              static_cast<std::uint32_t>(ids->GetId(2))});
  }
  return {std::move(mesh), ""};
}

}  // namespace lathesim::render
