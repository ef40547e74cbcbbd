#include "render/mesh_files.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

std::vector<char> readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Eigen::Vector3f floatsAt(const std::vector<char>& bytes, std::size_t offset) {
  float f[3];
  std::memcpy(f, bytes.data() + offset, sizeof f);
  return {f[0], f[1], f[2]};
}

TEST(BinaryStl, SizeCountAndOutwardNormals) {
  const TriangleMesh mesh = test::cylinder(30.0, 60.0, 48, 3);
  ASSERT_TRUE(isClosedAndOriented(mesh));
  test::TempDir dir;
  const auto file = dir.path() / "part.stl";
  writeBinaryStl(mesh, file);

  const std::vector<char> bytes = readBytes(file);
  const std::size_t n = mesh.triangles.size();
  ASSERT_EQ(bytes.size(), 84 + 50 * n);
  EXPECT_NE(std::string(bytes.data(), 5), "solid");  // not mistaken for ASCII STL
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, n);

  // Facet 0 is the side triangle at angles 0 and 2π/48: its normal points radially outward,
  // at half that angle.
  const Eigen::Vector3f normal0 = floatsAt(bytes, 84);
  const double half = M_PI / 48;
  EXPECT_NEAR(normal0.x(), std::cos(half), 1e-5);
  EXPECT_NEAR(normal0.y(), std::sin(half), 1e-5);
  EXPECT_NEAR(normal0.z(), 0.0, 1e-6);
  // Its first vertex is (30, 0, 0), stored after the normal.
  const Eigen::Vector3f v0 = floatsAt(bytes, 84 + 12);
  EXPECT_FLOAT_EQ(v0.x(), 30.0f);
  EXPECT_FLOAT_EQ(v0.y(), 0.0f);
  EXPECT_FLOAT_EQ(v0.z(), 0.0f);
  // The last facet is on the z = 60 cap: +Z; the one before on the z = 0 cap: −Z.
  const Eigen::Vector3f last = floatsAt(bytes, 84 + 50 * (n - 1));
  EXPECT_NEAR(last.z(), 1.0, 1e-6);
  const Eigen::Vector3f beforeLast = floatsAt(bytes, 84 + 50 * (n - 2));
  EXPECT_NEAR(beforeLast.z(), -1.0, 1e-6);
  // Attribute byte count is zero.
  EXPECT_EQ(bytes[84 + 48], 0);
  EXPECT_EQ(bytes[84 + 49], 0);
}

TEST(BinaryStl, EmptyMeshIsAValidEmptyFile) {
  test::TempDir dir;
  const auto file = dir.path() / "empty.stl";
  writeBinaryStl(TriangleMesh{}, file);
  EXPECT_EQ(std::filesystem::file_size(file), 84u);
}

TEST(BinaryStl, UnwritablePathThrows) {
  test::TempDir dir;
  EXPECT_THROW(writeBinaryStl(test::cylinder(1, 1, 8), dir.path() / "missing" / "part.stl"),
               std::runtime_error);
}

TEST(ToolpathVtp, OneCellPerMoveWithLineKindAndFeed) {
  const interp::Toolpath path = test::rapidThenFeed();
  test::TempDir dir;
  const auto file = dir.path() / "toolpath.vtp";
  writeToolpathVtp(path, file);

  vtkNew<vtkXMLPolyDataReader> reader;
  const std::string name = file.string();
  reader->SetFileName(name.c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  ASSERT_EQ(data->GetNumberOfCells(), 2);
  ASSERT_EQ(data->GetNumberOfLines(), 2);

  vtkCellData* cells = data->GetCellData();
  vtkDataArray* line = cells->GetArray("line");
  vtkDataArray* kind = cells->GetArray("kind");
  vtkDataArray* feed = cells->GetArray("feed");
  ASSERT_NE(line, nullptr);
  ASSERT_NE(kind, nullptr);
  ASSERT_NE(feed, nullptr);
  EXPECT_EQ(line->GetDataType(), VTK_INT);
  EXPECT_EQ(kind->GetDataType(), VTK_INT);
  EXPECT_EQ(feed->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(line->GetTuple1(0), 3);
  EXPECT_EQ(line->GetTuple1(1), 4);
  EXPECT_EQ(kind->GetTuple1(0), 0);  // rapid
  EXPECT_EQ(kind->GetTuple1(1), 1);  // feed
  EXPECT_EQ(feed->GetTuple1(0), 0.0);
  EXPECT_EQ(feed->GetTuple1(1), 0.2);

  // The feed's end points: (radius, 0, Z).
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  data->GetCellPoints(1, count, ids);
  ASSERT_EQ(count, 2);
  double p[3];
  data->GetPoint(ids[0], p);
  EXPECT_EQ(p[0], 29.0);
  EXPECT_EQ(p[1], 0.0);
  EXPECT_EQ(p[2], 62.0);
  data->GetPoint(ids[1], p);
  EXPECT_EQ(p[0], 29.0);
  EXPECT_EQ(p[2], 10.0);
}

TEST(ToolpathVtp, ArcIsOnePolylineCellAlongTheCircle) {
  // G02 a quarter turn of radius 5 about (15, -5), from (20, -5) to (15, 0), then G03 back.
  // Chords of sagitta ≤ 5/1000 may sweep 2·acos(0.999) = 0.08945 rad: 90° = 1.5708 rad
  // takes ceil(17.56) = 18 chords, 19 points.
  interp::Toolpath path = test::rapidThenFeed();
  auto arc = test::move(interp::MoveKind::ArcCW, 20, -5, 15, 0, 5, 0.1);
  arc.center = RZ(15, -5);
  path.moves.push_back(arc);
  arc.kind = interp::MoveKind::ArcCCW;
  std::swap(arc.from, arc.to);
  arc.line = 6;
  path.moves.push_back(arc);
  test::TempDir dir;
  const auto file = dir.path() / "arcs.vtp";
  writeToolpathVtp(path, file);

  vtkNew<vtkXMLPolyDataReader> reader;
  const std::string name = file.string();
  reader->SetFileName(name.c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  ASSERT_EQ(data->GetNumberOfCells(), 4);
  vtkDataArray* kind = data->GetCellData()->GetArray("kind");
  vtkDataArray* feed = data->GetCellData()->GetArray("feed");
  EXPECT_EQ(kind->GetTuple1(2), 2);  // cw
  EXPECT_EQ(kind->GetTuple1(3), 3);  // ccw
  EXPECT_EQ(feed->GetTuple1(2), 0.1);
  EXPECT_EQ(data->GetCellData()->GetArray("line")->GetTuple1(3), 6);

  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  data->GetCellPoints(2, count, ids);
  ASSERT_EQ(count, 19);
  double p[3];
  data->GetPoint(ids[0], p);
  EXPECT_EQ(p[0], 20.0);
  EXPECT_EQ(p[2], -5.0);
  data->GetPoint(ids[count - 1], p);
  EXPECT_EQ(p[0], 15.0);
  EXPECT_EQ(p[2], 0.0);
  for (vtkIdType k = 0; k < count; ++k) {
    data->GetPoint(ids[k], p);
    EXPECT_NEAR(std::hypot(p[0] - 15.0, p[2] + 5.0), 5.0, 1e-9);  // on the circle
    EXPECT_GE(p[0], 15.0 - 1e-9);  // in the quarter between the ends
    EXPECT_GE(p[2], -5.0 - 1e-9);
  }
  // The G03 back runs through the same quarter.
  data->GetCellPoints(3, count, ids);
  ASSERT_EQ(count, 19);
  data->GetPoint(ids[9], p);  // halfway: 45°, (15 + 5/√2, -5 + 5/√2)
  EXPECT_NEAR(p[0], 15 + 5 * M_SQRT1_2, 1e-9);
  EXPECT_NEAR(p[2], -5 + 5 * M_SQRT1_2, 1e-9);
}

TEST(ToolpathVtp, EmptyToolpathReadsBackEmpty) {
  test::TempDir dir;
  const auto file = dir.path() / "empty.vtp";
  writeToolpathVtp(interp::Toolpath{}, file);
  vtkNew<vtkXMLPolyDataReader> reader;
  const std::string name = file.string();
  reader->SetFileName(name.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);
}

}  // namespace
}  // namespace lathesim::render
