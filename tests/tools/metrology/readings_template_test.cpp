// Readings templates (readings_template.hpp): the preamble asks for the test conditions, one row
// per measured stop; a file that holds readings is never overwritten without force.
#include "volcomp/metrology/readings_template.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "file_contents.hpp"
#include "temp_paths.hpp"
#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;
using volcomp::testing::ReadText;
using volcomp::testing::TempPath;

TEST(MetrologyReadingsTemplate, PreambleAndRows) {
  TemplateHeader h;
  h.description = "fill in";
  h.known = {{"axis", "X"}, {"program", "x.ngc"}};
  h.omit = {"date"};
  const std::string pre = TemplatePreamble(h);
  EXPECT_EQ(pre.rfind("# fill in\n# machine:\n# axis: X\n# operator:\n", 0), 0u) << pre;
  EXPECT_NE(pre.find("# program: x.ngc\n"), std::string::npos);
  EXPECT_EQ(pre.find("# date:"), std::string::npos);
  const auto moves = ValueOf(BuildCycle({0.0, 10.0}, Cycle::kLinear, 1, 1.0));
  EXPECT_EQ(TemplateRows(moves, ""), "0.000,up,1,\n10.000,up,1,\n10.000,down,1,\n0.000,down,1,\n");
  EXPECT_EQ(TemplateRows(moves, "PPN").substr(0, 16), "PPN,0.000,up,1,\n");
}

TEST(MetrologyReadingsTemplate, ATemplateWithReadingsIsRefusedUnlessForced) {
  const std::string path = TempPath("template_test_x.csv");
  std::filesystem::remove(path);
  EXPECT_FALSE(ReadingsAtRisk(path));
  ASSERT_TRUE(WriteTemplate("target_mm,direction,run,deviation_um\n0,up,1,\n", path, false).ok());
  EXPECT_FALSE(ReadingsAtRisk(path));  // an empty template may be written again
  ASSERT_TRUE(
      WriteTemplate("target_mm,direction,run,deviation_um\n0,up,1,2.5\n", path, false).ok());
  ExpectFailure(RefuseToOverwriteReadings(path, false), Error::kInputInvalid,
                {path + " already holds readings (line 2)", "give --force"});
  ExpectFailure(WriteTemplate("new", path, false), Error::kInputInvalid, {"already holds"});
  EXPECT_EQ(ReadText(path), "target_mm,direction,run,deviation_um\n0,up,1,2.5\n");
  EXPECT_TRUE(WriteTemplate("new", path, true).ok());
  EXPECT_EQ(ReadText(path), "new");
  ExpectFailure(RefuseToOverwriteReadings(path, false), Error::kInputInvalid,
                {path + " exists and is not a readings template"});
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace volcomp::metrology
