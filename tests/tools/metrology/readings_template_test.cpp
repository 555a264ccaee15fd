// Readings templates (readings_template.hpp): the preamble asks for the test conditions, one row
// per measured stop; a file that holds readings is never overwritten without force.
#include "volcomp/metrology/readings_template.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::Must;

std::string Temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("volcomp_template_test_" + name)).string();
}

std::string Read(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(MetrologyReadingsTemplate, PreambleAndRows) {
  TemplateHeader h;
  h.description = "fill in";
  h.known = {{"axis", "X"}, {"program", "x.ngc"}};
  h.omit = {"date"};
  const std::string pre = TemplatePreamble(h);
  EXPECT_EQ(pre.rfind("# fill in\n# machine:\n# axis: X\n# operator:\n", 0), 0u) << pre;
  EXPECT_NE(pre.find("# program: x.ngc\n"), std::string::npos);
  EXPECT_EQ(pre.find("# date:"), std::string::npos);
  const auto moves = Must(BuildCycle({0.0, 10.0}, Cycle::kLinear, 1, 1.0));
  EXPECT_EQ(TemplateRows(moves, ""), "0.000,up,1,\n10.000,up,1,\n10.000,down,1,\n0.000,down,1,\n");
  EXPECT_EQ(TemplateRows(moves, "PPN").substr(0, 16), "PPN,0.000,up,1,\n");
}

TEST(MetrologyReadingsTemplate, ATemplateWithReadingsIsRefusedUnlessForced) {
  const std::string path = Temp("x.csv");
  std::filesystem::remove(path);
  EXPECT_FALSE(ReadingsAtRisk(path));
  ASSERT_TRUE(WriteTemplate("target_mm,direction,run,deviation_um\n0,up,1,\n", path, false).ok());
  EXPECT_FALSE(ReadingsAtRisk(path));  // an empty template may be written again
  ASSERT_TRUE(
      WriteTemplate("target_mm,direction,run,deviation_um\n0,up,1,2.5\n", path, false).ok());
  ExpectFailure(RefuseToOverwriteReadings(path, false), Error::kInputInvalid,
                {path + " already holds readings (line 2)", "give --force"});
  ExpectFailure(WriteTemplate("new", path, false), Error::kInputInvalid, {"already holds"});
  EXPECT_EQ(Read(path), "target_mm,direction,run,deviation_um\n0,up,1,2.5\n");
  EXPECT_TRUE(WriteTemplate("new", path, true).ok());
  EXPECT_EQ(Read(path), "new");
  ExpectFailure(RefuseToOverwriteReadings(path, false), Error::kInputInvalid,
                {path + " exists and is not a readings template"});
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace volcomp::metrology
