#include "interp/output/toolpath_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

TEST(ToolpathCsv, NumbersHaveAtMostFourDecimalsAndNoTrailingZeros) {
  EXPECT_EQ(csvNumber(130.0), "130");
  EXPECT_EQ(csvNumber(62.5), "62.5");
  EXPECT_EQ(csvNumber(0.1), "0.1");
  EXPECT_EQ(csvNumber(-110.0), "-110");
  EXPECT_EQ(csvNumber(0.0), "0");
  EXPECT_EQ(csvNumber(-0.00001), "0");
  EXPECT_EQ(csvNumber(1.23456), "1.2346");
  EXPECT_EQ(csvNumber(12.7), "12.7");
}

TEST(ToolpathCsv, WritesDiametersOneRowPerMove) {
  const auto result = test::run("G00 X130 Z5\nG94 X120 Z-110 F300\n");
  ASSERT_TRUE(result.ok());
  std::ostringstream out;
  writeToolpathCsv(result.toolpath, out);
  EXPECT_EQ(out.str(),
            "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s,thread_deg,spindle\n"
            "1,rapid,200,200,130,5,0,,,0,,\n"
            "2,rapid,130,5,130,-110,0,,,0,,\n"
            "2,feed,130,-110,120,-110,300,,,0,,\n"
            "2,feed,120,-110,120,5,300,,,0,,\n"
            "2,rapid,120,5,130,5,0,,,0,,\n");
}

TEST(ToolpathCsv, WritesArcKindsAndTheirCentresAsDiameters) {
  // G02 from (10, 0) to (10, -8) with R5: centre (13, -4), written X26 Z-4 (the centres are
  // worked out in arc_move_test.cpp). G03 back to Z0 with R5: travelling right, the left
  // (a G03's centre) is up, so the same centre (13, -4): the same groove run backwards.
  const auto result = test::run("G00 X20 Z0\nG02 Z-8 R5 F0.1\nG03 Z0 R5\n");
  ASSERT_TRUE(result.ok());
  std::ostringstream out;
  writeToolpathCsv(result.toolpath, out);
  EXPECT_EQ(out.str(),
            "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s,thread_deg,spindle\n"
            "1,rapid,200,200,20,0,0,,,0,,\n"
            "2,cw,20,0,20,-8,0.1,26,-4,0,,\n"
            "3,ccw,20,-8,20,0,0.1,26,-4,0,,\n");
}

// A thread move: its lead in feed, then its start angle and the spindle's direction (M04) at
// the end. G32 Z-20.5 F2 Q90000 from Z5 is 12.75 turns from 90°, so the chained G32 starts at
// 90 + 4590 ≡ 0°.
TEST(ToolpathCsv, WritesThreadMovesWithTheirStartAngleAndSpindleDirection) {
  const auto result = test::run("M04\nG00 X30 Z5\nG32 Z-20.5 F2 Q90000\nG32 X32 Z-21\n");
  ASSERT_TRUE(result.ok());
  std::ostringstream out;
  writeToolpathCsv(result.toolpath, out);
  EXPECT_EQ(out.str(),
            "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s,thread_deg,spindle\n"
            "2,rapid,200,200,30,5,0,,,0,,\n"
            "3,thread,30,5,30,-20.5,2,,,0,90,ccw\n"
            "4,thread,30,-20.5,32,-21,2,,,0,0,ccw\n");
  std::istringstream in(out.str());
  const auto rows = readToolpathCsv(in);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2].kind, "thread");
  ASSERT_TRUE(rows[2].threadDeg && rows[2].spindle);
  EXPECT_DOUBLE_EQ(*rows[2].threadDeg, 0);
  EXPECT_EQ(*rows[2].spindle, "ccw");
  EXPECT_FALSE(rows[0].threadDeg);
}

TEST(ToolpathCsv, ReadsWhatItWrote) {
  std::istringstream in(
      "line,kind,x0,z0,x1,z1,feed\n"
      "1,rapid,200,200,130,5,0\n"
      "2,feed,130,-110,120,-110.5,0.25\n");
  const auto rows = readToolpathCsv(in);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].line, 1);
  EXPECT_EQ(rows[0].kind, "rapid");
  EXPECT_DOUBLE_EQ(rows[0].x1, 130);
  EXPECT_EQ(rows[1].kind, "feed");
  EXPECT_DOUBLE_EQ(rows[1].x0, 130);
  EXPECT_DOUBLE_EQ(rows[1].z0, -110);
  EXPECT_DOUBLE_EQ(rows[1].x1, 120);
  EXPECT_DOUBLE_EQ(rows[1].z1, -110.5);
  EXPECT_DOUBLE_EQ(rows[1].feed, 0.25);
}

TEST(ToolpathCsv, ReadsArcCentresAndTimesOfTheFullHeader) {
  std::istringstream in(
      "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s\n"
      "3,ccw,20,0,30,-5,0.1,20,-5,1.25\n"
      "4,feed,30,-5,30,-9,0.1,,,0.5\n");
  const auto rows = readToolpathCsv(in);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].kind, "ccw");
  ASSERT_TRUE(rows[0].xc && rows[0].zc && rows[0].timeS);
  EXPECT_DOUBLE_EQ(*rows[0].xc, 20);
  EXPECT_DOUBLE_EQ(*rows[0].zc, -5);
  EXPECT_DOUBLE_EQ(*rows[0].timeS, 1.25);
  EXPECT_FALSE(rows[1].xc.has_value());
  ASSERT_TRUE(rows[1].timeS.has_value());
  EXPECT_DOUBLE_EQ(*rows[1].timeS, 0.5);
}

TEST(ToolpathCsv, RejectsMissingHeaderAndBadRows) {
  std::istringstream noHeader("1,rapid,0,0,1,1,0\n");
  EXPECT_THROW(readToolpathCsv(noHeader), std::runtime_error);
  std::istringstream badKind("line,kind,x0,z0,x1,z1,feed\n1,arc,0,0,1,1,0\n");
  EXPECT_THROW(readToolpathCsv(badKind), std::runtime_error);
  std::istringstream badNumber("line,kind,x0,z0,x1,z1,feed\n1,feed,a,0,1,1,0\n");
  EXPECT_THROW(readToolpathCsv(badNumber), std::runtime_error);
  std::istringstream shortRow("line,kind,x0,z0,x1,z1,feed,xc,zc,time_s\n1,feed,0,0,1,1,0\n");
  EXPECT_THROW(readToolpathCsv(shortRow), std::runtime_error);
}

}  // namespace
}  // namespace lathesim::interp
