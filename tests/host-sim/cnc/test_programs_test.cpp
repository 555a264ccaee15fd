// The measurement programs: G-code the CNC's reader accepts with one dwell per listed stop, and
// the plans the metrology code refuses, refused with its reason.
#include "volcomp/sim/test_programs.hpp"

#include <gtest/gtest.h>

#include <string>

#include "volcomp/sim/gcode.hpp"

namespace volcomp::sim {
namespace {

size_t Dwells(const Program& p) {
  size_t n = 0;
  for (const ProgramBlock& b : p) n += b.kind == ProgramBlock::Kind::kDwell ? 1 : 0;
  return n;
}

TEST(SimTestPrograms, GostAxisProgramDwellsAtEveryStop) {
  CycleOptions c;
  c.runs = 2;
  const Expected<TestProgram> p = GostAxisProgram(1, {10, 20, 30}, {5, 15, 25}, c);
  ASSERT_TRUE(p.ok()) << p.error().message;
  EXPECT_EQ(p->name, "GOST 27843 Y");
  ASSERT_EQ(p->stops.size(), 1u + 3u * 2u * 2u);  // datum + 3 targets, 2 runs, both directions
  EXPECT_TRUE(p->stops[0].datum);
  for (size_t i = 1; i < p->stops.size(); ++i) {
    EXPECT_FALSE(p->stops[i].datum);
    EXPECT_EQ(p->stops[i].point_mm[0], 10);  // on the line through (10, ., 30) along Y
    EXPECT_EQ(p->stops[i].point_mm[2], 30);
    EXPECT_EQ(p->stops[i].point_mm[1], p->stops[i].along_mm);
  }
  const Expected<Program> parsed = ParseGcode(p->gcode, p->name);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  EXPECT_EQ(Dwells(*parsed), p->stops.size());
}

TEST(SimTestPrograms, PlansTheMetrologyCodeRefusesAreFailures) {
  const CycleOptions c;
  const Expected<TestProgram> axis = GostAxisProgram(3, {0, 0, 0}, {5, 15}, c);
  ASSERT_FALSE(axis.ok());
  EXPECT_EQ(axis.error().code, Error::kInvalidArgument);
  EXPECT_NE(axis.error().message.find("axis must be 0..2"), std::string::npos);

  const Expected<TestProgram> one = ParametricProgram(0, {0, 0, 0}, {5}, c);
  ASSERT_FALSE(one.ok());
  EXPECT_EQ(one.error().code, Error::kInvalidArgument);
  EXPECT_NE(one.error().message.find("at least 2 targets"), std::string::npos)
      << one.error().message;

  const Expected<TestProgram> point = DiagonalProgram("-X-Y-Z", {1, 2, 3}, {1, 2, 3}, 10, c);
  ASSERT_FALSE(point.ok());
  EXPECT_EQ(point.error().code, Error::kInvalidArgument);
  EXPECT_NE(point.error().message.find("same point"), std::string::npos) << point.error().message;
}

}  // namespace
}  // namespace volcomp::sim
