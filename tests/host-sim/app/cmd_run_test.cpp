// `volcomp-sim run` on its command line: the JSON holds every figure the text prints, the usage
// refusals, a missing program file.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "sim_runner.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::sim {
namespace {

// The program file of one test case (its own name: the cases run in parallel processes, and a
// case rewriting a file another one is reading made that one fail).
std::string WriteProgram(const std::string& name) {
  const std::string path = testing::TempPath(name);
  std::ofstream f(path);
  f << "G21 G90 G17\nG0 X100 Y100 Z100\nG1 X150 F6000\nG2 X150 Y100 I-10 J0\nG4 P0.05\nM2\n";
  return path;
}

// The number after `label` in the text, e.g. "cutting max 1.234 um".
double After(const std::string& text, const std::string& label) {
  const size_t at = text.find(label);
  if (at == std::string::npos) return -1;
  return std::stod(text.substr(at + label.size()));
}

TEST(SimRunCommand, TheJsonHoldsEveryFigureTheTextPrints) {
  const std::string program = WriteProgram("cmd_run_json.ngc");
  const SimRun text = Sim({"run", program});
  ASSERT_EQ(text.code, 0) << text.err;
  const SimRun json = Sim({"run", program, "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const auto parsed = tools::ParseJson(json.out, "run --json");
  ASSERT_TRUE(parsed.ok()) << json.out;
  const tools::JsonValue& j = *parsed;
  for (const char* key :
       {"program", "machine", "table_crc", "cutting_max_error_um", "cutting_rms_error_um",
        "rapid_max_error_um", "rest_max_error_um", "lost_steps", "timing_violations", "segments"}) {
    EXPECT_NE(j.get(key), nullptr) << key;
  }
  EXPECT_EQ(j.get("machine")->string, "ideal");
  EXPECT_TRUE(j.get("table_crc")->is_null());
  auto number = [&](const char* key) { return j.get(key)->number; };
  EXPECT_NEAR(After(text.out, "cutting max "), number("cutting_max_error_um"), 0.0005);
  EXPECT_NEAR(After(text.out, ", rms "), number("cutting_rms_error_um"), 0.0005);
  EXPECT_NEAR(After(text.out, "rapid max "), number("rapid_max_error_um"), 0.0005);
  EXPECT_NEAR(After(text.out, "at rest max "), number("rest_max_error_um"), 0.0005);
  EXPECT_EQ(After(text.out, "lost steps "), number("lost_steps"));
  EXPECT_EQ(number("lost_steps"), 0);
  EXPECT_EQ(number("timing_violations"), 0);
  // One row per program line and kind, each also a text row "line  kind  samples  max".
  const tools::JsonValue& segments = *j.get("segments");
  ASSERT_GE(segments.array.size(), 3u);
  for (const tools::JsonValue& s : segments.array) {
    char row[80];
    std::snprintf(row, sizeof row, "%4d  %-8s %8llu  %8.3f um\n",
                  static_cast<int>(s.get("line")->number), s.get("kind")->string.c_str(),
                  static_cast<unsigned long long>(s.get("samples")->number),
                  s.get("max_error_um")->number);
    EXPECT_NE(text.out.find(row), std::string::npos) << row << text.out;
  }
}

TEST(SimRunCommand, RefusesWhatItCannotRun) {
  const std::string program = WriteProgram("cmd_run_refusals.ngc");
  const SimRun none = Sim({"run"});
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.err, "volcomp-sim run: give one program file (PROGRAM.ngc)\n");
  const SimRun machine = Sim({"run", program, "--machine", "new"});
  EXPECT_EQ(machine.code, 2);
  EXPECT_EQ(machine.err, "volcomp-sim run: --machine must be ideal or worn\n");
  const std::string ini = testing::TempPath("cmd_run_bad.ini");
  std::ofstream(ini) << "[axis X]\n[axis Y]\nmax_rate = fast\n[axis Z]\n";
  const SimRun settings = Sim({"run", program, "--settings", ini});
  EXPECT_EQ(settings.code, 1);
  EXPECT_NE(settings.err.find("cmd_run_bad.ini:3:"), std::string::npos) << settings.err;
  const SimRun ballbar = Sim({"run", program, "--ballbar", "1,2"});
  EXPECT_EQ(ballbar.code, 2);
  EXPECT_EQ(ballbar.err, "volcomp-sim run: --ballbar needs the pivot as X,Y,Z (mm), not \"1,2\"\n");
  const SimRun missing = Sim({"run", testing::TempPath("no_such_program.ngc")});
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("no_such_program.ngc"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace volcomp::sim
