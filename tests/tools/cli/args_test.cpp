// Option parsing: negative numbers and `--` are values wherever a value is expected, unknown or
// repeated options are refused, defaults come from the option table.
#include "volcomp/tools/args.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"

namespace volcomp::tools {
namespace {

using volcomp::testing::RunCli;

const std::vector<OptionSpec> kSpec = {
    {"--can", nullptr, "SPEC"},
    {"--range", nullptr, "X=MIN:MAX"},
    {"--tool-offset-mm", nullptr, "X,Y,Z", "mm"},
    {"--name", nullptr, "NAME"},
    {"--start", nullptr, "S", "mm", "0"},
    {"--output", "-o", "FILE", nullptr, "-"},
    {"--info", nullptr, "KEY=VALUE", nullptr, nullptr, "", true},
    {"--json"},
};

TEST(Args, NegativeNumbersArePositionalValues) {
  for (const std::string v : {"-5000", "-0.5", "-1e3", "-0x10", "+7"}) {
    Args a({"write", "2018:1", v, "--can", "x"}, &kSpec);
    EXPECT_EQ(a.value("--can"), "x");
    EXPECT_EQ(a.positionals(), (std::vector<std::string>{"write", "2018:1", v})) << v;
    EXPECT_NO_THROW(a.finish());
  }
  Args legacy({"write", "2018:1", "-5000", "--can", "x"});
  EXPECT_EQ(legacy.value("--can"), "x");
  EXPECT_EQ(legacy.positionals(), (std::vector<std::string>{"write", "2018:1", "-5000"}));
  EXPECT_NO_THROW(legacy.finish());
}

TEST(Args, DoubleDashEndsTheOptions) {
  Args a({"--can", "x", "write", "--", "-5000", "--json", "-o"}, &kSpec);
  EXPECT_FALSE(a.flag("--json"));
  EXPECT_EQ(a.value("-o", "--output"), "-");  // the default, not the word after `--`
  EXPECT_EQ(a.positionals(), (std::vector<std::string>{"write", "-5000", "--json", "-o"}));
  a.value("--can");
  EXPECT_NO_THROW(a.finish());

  Args legacy({"--can", "x", "--", "-5000", "--json"});
  EXPECT_FALSE(legacy.flag("--json"));
  EXPECT_EQ(legacy.value("--can"), "x");
  EXPECT_EQ(legacy.positionals(), (std::vector<std::string>{"-5000", "--json"}));
  EXPECT_NO_THROW(legacy.finish());
}

TEST(Args, OptionValuesMayStartWithAMinus) {
  Args a({"--range", "X=-100:100", "--tool-offset-mm", "-1,2,3", "--name", "-X-Y-Z", "--start",
          "-5", "--info=k=-1", "--info", "-v=2"},
         &kSpec);
  EXPECT_EQ(a.value("--range"), "X=-100:100");
  EXPECT_EQ(a.value("--tool-offset-mm"), "-1,2,3");
  EXPECT_EQ(a.value("--name"), "-X-Y-Z");
  EXPECT_EQ(a.number("--start"), -5.0);
  EXPECT_EQ(a.values("--info"), (std::vector<std::string>{"k=-1", "-v=2"}));
  EXPECT_TRUE(a.positionals().empty());
  EXPECT_NO_THROW(a.finish());
  Args b({"--name=-X-Y-Z"}, &kSpec);
  EXPECT_EQ(b.value("--name"), "-X-Y-Z");
}

TEST(Args, DefaultsComeFromTheTable) {
  Args a({}, &kSpec);
  EXPECT_EQ(a.number("--start"), 0.0);
  EXPECT_EQ(a.value("--output"), "-");
  EXPECT_FALSE(a.value("--name").has_value());
  Args b({"-o", "f.ngc"}, &kSpec);
  EXPECT_EQ(b.value("-o", "--output"), "f.ngc");
}

std::string UsageErrorOf(std::vector<std::string> words) {
  try {
    Args a(std::move(words), &kSpec);
    a.value("--can");
    a.value("--name");
    a.flag("--json");
    a.positionals();
    a.finish();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Args, RefusesUnknownRepeatedAndMalformedOptions) {
  EXPECT_EQ(UsageErrorOf({"--bogus"}), "unknown option \"--bogus\"");
  EXPECT_EQ(UsageErrorOf({"-x"}), "unknown option \"-x\"");
  EXPECT_EQ(UsageErrorOf({"--name", "a", "--name", "b"}), "option --name is given twice");
  EXPECT_EQ(UsageErrorOf({"--json=1"}), "option --json takes no value");
  EXPECT_EQ(UsageErrorOf({"--name"}), "option --name needs a value (NAME)");
  EXPECT_EQ(UsageErrorOf({"--name", "--"}), "option --name needs a value (NAME)");
  EXPECT_EQ(UsageErrorOf({"--start", "1"}), "option --start does not apply here");
  EXPECT_EQ(UsageErrorOf({"-"}), "");  // standard input is a positional
}

TEST(Args, AskingForAnUndeclaredOptionIsAProgrammingError) {
  Args a({}, &kSpec);
  EXPECT_THROW(a.value("--nope"), std::logic_error);
  EXPECT_THROW(a.flag("--name"), std::logic_error);   // declared with a value
  EXPECT_THROW(a.value("--json"), std::logic_error);  // declared as a flag
}

// The case: `sdo write 2018:1 -5000` stopped at the option parser with exit 2. Now the
// value reaches the command, which fails later only because there is no bus.
TEST(VolcompCli, SdoWriteTakesANegativeValue) {
  for (const auto& words : std::vector<std::vector<std::string>>{
           {"sdo", "write", "2018:1", "-5000", "--can", "slcan-tcp:127.0.0.1:1"},
           {"sdo", "write", "2018:1", "--can", "slcan-tcp:127.0.0.1:1", "--", "-5000"}}) {
    const auto r = RunCli(words);
    EXPECT_NE(r.code, kExitUsage) << r.err;
    EXPECT_EQ(r.err.find("unexpected argument"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("127.0.0.1"), std::string::npos) << r.err;  // it tried the bus
  }
  const auto bad = RunCli({"sdo", "write", "2018:1", "-5x", "--can", "slcan-tcp:127.0.0.1:1"});
  EXPECT_EQ(bad.code, kExitUsage);
  EXPECT_NE(bad.err.find("unknown option \"-5x\""), std::string::npos) << bad.err;
}

TEST(VolcompCli, NegativeCoordinatesInBuildAndProgramOptions) {
  const std::string img =
      (std::filesystem::temp_directory_path() / "volcomp_args_neg.vct").string();
  auto r = RunCli({"build", "model", "--model", "s500", "--tool-offset-mm", "-1,2,3", "--range",
                   "X=-100:100,Y=0:40,Z=0:40", "--spacing-mm", "20", "--resolution-nm",
                   "X=1000,Y=1000,Z=1000", "-o", img});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lattice X: -100 .. 100 mm"), std::string::npos) << r.out;
  std::filesystem::remove(img);
  r = RunCli({"program", "diagonal", "--p1", "-10,-20,-30", "--p2", "90,80,70", "--increment-mm",
              "20", "--name", "-X-Y-Z"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("G1 X-10.000 Y-20.000 Z-30.000 (P1 up run 1)"), std::string::npos) << r.out;
  r = RunCli({"program", "positioning", "--start", "-200", "--end", "-20", "--pitch", "5"});
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace volcomp::tools
