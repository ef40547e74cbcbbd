// toolpath.vtp as VTK's own XML reader reads it back: cells, points and cell data.

#include "render/toolpath_vtp.hpp"

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

// The file as VTK's own XML reader reads it.
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  const std::string name = file.string();
  reader->SetFileName(name.c_str());
  reader->Update();
  return reader->GetOutput();
}

interp::MoveSpool spoolOf(const interp::Toolpath& path) {
  interp::MoveSpool spool;
  for (const interp::Move& move : path.moves) spool.take(move);
  return spool;
}

TEST(ToolpathVtp, OneCellPerMoveWithLineKindAndFeed) {
  const interp::Toolpath path = test::rapidThenFeed();
  test::TempDir dir;
  const auto file = dir.path() / "toolpath.vtp";
  writeToolpathVtp(spoolOf(path), file);

  const vtkSmartPointer<vtkPolyData> data = readVtp(file);
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
  writeToolpathVtp(spoolOf(path), file);

  const vtkSmartPointer<vtkPolyData> data = readVtp(file);
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
  writeToolpathVtp(interp::MoveSpool{}, file);
  EXPECT_EQ(readVtp(file)->GetNumberOfCells(), 0);
}

// 10 000 moves: the counts, the last cell's line and its points, past any buffer's size.
TEST(ToolpathVtp, ManyMovesReadBackWhole) {
  interp::MoveSpool spool;
  for (int i = 0; i < 10000; ++i)
    spool.take(test::move(i % 2 ? interp::MoveKind::Feed : interp::MoveKind::Rapid, 20 + i % 2, -i, 21 - i % 2, -i - 1, i + 1, 0.1 * (i % 2)));
  test::TempDir dir;
  const auto file = dir.path() / "many.vtp";
  writeToolpathVtp(spool, file);
  const vtkSmartPointer<vtkPolyData> data = readVtp(file);
  ASSERT_EQ(data->GetNumberOfCells(), 10000);
  ASSERT_EQ(data->GetNumberOfPoints(), 20000);
  EXPECT_EQ(data->GetCellData()->GetArray("line")->GetTuple1(9999), 10000);
  EXPECT_EQ(data->GetCellData()->GetArray("kind")->GetTuple1(9999), 1);
  EXPECT_EQ(data->GetCellData()->GetArray("feed")->GetTuple1(9998), 0.0);
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  data->GetCellPoints(9999, count, ids);
  ASSERT_EQ(count, 2);
  double p[3];
  data->GetPoint(ids[1], p);
  EXPECT_EQ(p[0], 20.0);
  EXPECT_EQ(p[2], -10000.0);
}

}  // namespace
}  // namespace lathesim::render
