// toolpath.vtp as VTK's own XML reader reads it back: cells, points and cell data.

#include "render/toolpath_vtp.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include "tests/render/test_meshes.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::render {
namespace {

// The file as VTK's own XML reader reads it; whatever the reader complains of (a bad
// compression header, an offset past the data) fails the test, or an empty toolpath that
// could not be read would pass for one read back empty.
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  vtkNew<vtkCallbackCommand> complaint;
  complaint->SetCallback([](vtkObject*, unsigned long event, void*, void* message) {
    ADD_FAILURE() << vtkCommand::GetStringFromEventId(event) << ": " << static_cast<const char*>(message);
  });
  reader->AddObserver(vtkCommand::ErrorEvent, complaint);
  reader->AddObserver(vtkCommand::WarningEvent, complaint);
  const std::string name = file.string();
  reader->SetFileName(name.c_str());
  reader->Update();
  return reader->GetOutput();
}

// A cell's points, each (radius, 0, Z).
std::vector<std::array<double, 3>> cellPoints(vtkPolyData* data, vtkIdType cell) {
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  data->GetCellPoints(cell, count, ids);
  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(count));
  for (vtkIdType k = 0; k < count; ++k) data->GetPoint(ids[k], points[static_cast<std::size_t>(k)].data());
  return points;
}

interp::MoveSpool spoolOf(const interp::Toolpath& path) {
  interp::MoveSpool spool;
  for (const interp::Move& move : path.moves) spool.take(move);
  return spool;
}

// The moves written to toolpath.vtp in a scratch folder and read back.
vtkSmartPointer<vtkPolyData> writtenAndRead(const interp::MoveSpool& moves) {
  test::TempDir dir;
  const auto file = dir.path() / "toolpath.vtp";
  writeToolpathVtp(moves, file);
  return readVtp(file);
}

TEST(ToolpathVtp, OneCellPerMoveWithLineKindAndFeed) {
  const interp::Toolpath path = test::rapidThenFeed();
  const vtkSmartPointer<vtkPolyData> data = writtenAndRead(spoolOf(path));
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

  // The feed's end points.
  const auto feedEnds = cellPoints(data, 1);
  ASSERT_EQ(feedEnds.size(), 2u);
  EXPECT_EQ(feedEnds[0], (std::array<double, 3>{29.0, 0.0, 62.0}));
  EXPECT_EQ(feedEnds[1], (std::array<double, 3>{29.0, 0.0, 10.0}));
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
  const vtkSmartPointer<vtkPolyData> data = writtenAndRead(spoolOf(path));
  ASSERT_EQ(data->GetNumberOfCells(), 4);
  vtkDataArray* kind = data->GetCellData()->GetArray("kind");
  vtkDataArray* feed = data->GetCellData()->GetArray("feed");
  EXPECT_EQ(kind->GetTuple1(2), 2);  // cw
  EXPECT_EQ(kind->GetTuple1(3), 3);  // ccw
  EXPECT_EQ(feed->GetTuple1(2), 0.1);
  EXPECT_EQ(data->GetCellData()->GetArray("line")->GetTuple1(3), 6);

  const auto cw = cellPoints(data, 2);
  ASSERT_EQ(cw.size(), 19u);
  EXPECT_EQ(cw.front(), (std::array<double, 3>{20.0, 0.0, -5.0}));
  EXPECT_EQ(cw.back(), (std::array<double, 3>{15.0, 0.0, 0.0}));
  for (const auto& p : cw) {
    EXPECT_NEAR(std::hypot(p[0] - 15.0, p[2] + 5.0), 5.0, 1e-9);  // on the circle
    EXPECT_GE(p[0], 15.0 - 1e-9);  // in the quarter between the ends
    EXPECT_GE(p[2], -5.0 - 1e-9);
  }
  // The G03 back runs through the same quarter.
  const auto ccw = cellPoints(data, 3);
  ASSERT_EQ(ccw.size(), 19u);
  EXPECT_NEAR(ccw[9][0], 15 + 5 * M_SQRT1_2, 1e-9);  // halfway: 45°, (15 + 5/√2, -5 + 5/√2)
  EXPECT_NEAR(ccw[9][2], -5 + 5 * M_SQRT1_2, 1e-9);
}

TEST(ToolpathVtp, EmptyToolpathReadsBackEmpty) {
  const vtkSmartPointer<vtkPolyData> data = writtenAndRead(interp::MoveSpool{});
  EXPECT_EQ(data->GetNumberOfCells(), 0);
  EXPECT_EQ(data->GetNumberOfPoints(), 0);
  ASSERT_NE(data->GetCellData()->GetArray("line"), nullptr);
  EXPECT_EQ(data->GetCellData()->GetArray("line")->GetNumberOfTuples(), 0);
}

// `moves` moves alternating rapid and feed, each 1 mm further down Z, line i + 1.
interp::MoveSpool zigzag(int moves) {
  interp::MoveSpool spool;
  for (int i = 0; i < moves; ++i)
    spool.take(test::move(i % 2 ? interp::MoveKind::Feed : interp::MoveKind::Rapid, 20 + i % 2, -i, 21 - i % 2, -i - 1, i + 1, 0.1 * (i % 2)));
  return spool;
}

// Many moves: the counts, the last cells' data and points, past any buffer's size and across
// many compressed blocks of 32 KiB. 8192 moves make every array whole blocks (its Int32 arrays
// one, its points twelve), so that the last block is a whole one too; 10 000 leave a shorter last
// block in each.
class ManyMoves : public testing::TestWithParam<int> {};

TEST_P(ManyMoves, ReadBackWhole) {
  const int moves = GetParam();
  const vtkSmartPointer<vtkPolyData> data = writtenAndRead(zigzag(moves));
  ASSERT_EQ(data->GetNumberOfCells(), moves);
  ASSERT_EQ(data->GetNumberOfPoints(), 2 * moves);
  vtkCellData* cells = data->GetCellData();
  for (const int cell : {0, moves / 2 + 1, moves - 2, moves - 1}) {
    SCOPED_TRACE(cell);
    EXPECT_EQ(cells->GetArray("line")->GetTuple1(cell), cell + 1);
    EXPECT_EQ(cells->GetArray("kind")->GetTuple1(cell), cell % 2);
    EXPECT_EQ(cells->GetArray("feed")->GetTuple1(cell), 0.1 * (cell % 2));
    const auto ends = cellPoints(data, cell);
    ASSERT_EQ(ends.size(), 2u);
    EXPECT_EQ(ends[0], (std::array<double, 3>{20.0 + cell % 2, 0.0, -1.0 * cell}));
    EXPECT_EQ(ends[1], (std::array<double, 3>{21.0 - cell % 2, 0.0, -1.0 * cell - 1.0}));
  }
}

INSTANTIATE_TEST_SUITE_P(ToolpathVtp, ManyMoves, testing::Values(8192, 10000));

// Compressed as vtkXMLWriter compresses by default: 10 000 straight moves take 88 B each raw
// (line and kind 4, feed 8, two points 48, their ids 16, the offset 8); compressed the file
// measured 92 242 B, 1/9.5 of that. The bound, 1/5, leaves room for another zlib and fails if
// the points or their ids (48 and 16 B a move) were left raw.
TEST(ToolpathVtp, IsZLibCompressed) {
  constexpr int kMoves = 10000;
  test::TempDir dir;
  const auto file = dir.path() / "many.vtp";
  writeToolpathVtp(zigzag(kMoves), file);
  const std::string text = lathesim::test::readFile(file);
  EXPECT_NE(text.find(" compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  const std::size_t rawBytes = 88 * kMoves;
  EXPECT_LT(text.size(), rawBytes / 5) << text.size() << " B";
}

TEST(ToolpathVtp, AnUnwritablePathThrowsNamingIt) {
  test::TempDir dir;
  const auto file = dir.path() / "no such folder" / "toolpath.vtp";
  try {
    writeToolpathVtp(zigzag(3), file);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + file.string() + ": No such file or directory");
  }
}

TEST(ToolpathVtp, AFullDiskThrowsSayingSo) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  try {
    writeToolpathVtp(zigzag(10000), "/dev/full");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write /dev/full: No space left on device");
  }
}

}  // namespace
}  // namespace lathesim::render
