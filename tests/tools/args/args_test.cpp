// Option parsing: negative numbers and `--` are values wherever a value is expected, unknown or
// repeated options are refused, defaults come from the option table.
#include "volcomp/args/args.hpp"

#include <gtest/gtest.h>

namespace volcomp::args {
namespace {

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
    EXPECT_EQ(a.Value("--can"), "x");
    EXPECT_EQ(a.Positionals(), (std::vector<std::string>{"write", "2018:1", v})) << v;
    EXPECT_TRUE(a.Finish().ok());
  }
  Args legacy({"write", "2018:1", "-5000", "--can", "x"});
  EXPECT_EQ(legacy.Value("--can"), "x");
  EXPECT_EQ(legacy.Positionals(), (std::vector<std::string>{"write", "2018:1", "-5000"}));
  EXPECT_TRUE(legacy.Finish().ok());
}

TEST(Args, DoubleDashEndsTheOptions) {
  Args a({"--can", "x", "write", "--", "-5000", "--json", "-o"}, &kSpec);
  EXPECT_FALSE(a.Flag("--json"));
  EXPECT_EQ(a.Value("-o", "--output"), "-");  // the default, not the word after `--`
  EXPECT_EQ(a.Positionals(), (std::vector<std::string>{"write", "-5000", "--json", "-o"}));
  a.Value("--can");
  EXPECT_TRUE(a.Finish().ok());

  Args legacy({"--can", "x", "--", "-5000", "--json"});
  EXPECT_FALSE(legacy.Flag("--json"));
  EXPECT_EQ(legacy.Value("--can"), "x");
  EXPECT_EQ(legacy.Positionals(), (std::vector<std::string>{"-5000", "--json"}));
  EXPECT_TRUE(legacy.Finish().ok());
}

TEST(Args, OptionValuesMayStartWithAMinus) {
  Args a({"--range", "X=-100:100", "--tool-offset-mm", "-1,2,3", "--name", "-X-Y-Z", "--start",
          "-5", "--info=k=-1", "--info", "-v=2"},
         &kSpec);
  EXPECT_EQ(a.Value("--range"), "X=-100:100");
  EXPECT_EQ(a.Value("--tool-offset-mm"), "-1,2,3");
  EXPECT_EQ(a.Value("--name"), "-X-Y-Z");
  EXPECT_EQ(a.Number("--start"), -5.0);
  EXPECT_EQ(a.Values("--info"), (std::vector<std::string>{"k=-1", "-v=2"}));
  EXPECT_TRUE(a.Positionals().empty());
  EXPECT_TRUE(a.Finish().ok());
  Args b({"--name=-X-Y-Z"}, &kSpec);
  EXPECT_EQ(b.Value("--name"), "-X-Y-Z");
}

TEST(Args, DefaultsComeFromTheTable) {
  Args a({}, &kSpec);
  EXPECT_EQ(a.Number("--start"), 0.0);
  EXPECT_EQ(a.Value("--output"), "-");
  EXPECT_FALSE(a.Value("--name").has_value());
  Args b({"-o", "f.ngc"}, &kSpec);
  EXPECT_EQ(b.Value("-o", "--output"), "f.ngc");
}

// The message of the usage failure the words give ("" when they are fine).
std::string UsageErrorOf(std::vector<std::string> words) {
  Args a(std::move(words), &kSpec);
  a.Value("--can");
  a.Value("--name");
  a.Flag("--json");
  a.Positionals();
  const Outcome r = a.Finish();
  if (r.ok()) return "";
  EXPECT_EQ(r.error().code, Error::kUsage);
  return r.error().message;
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

// A failed query keeps the first failure; later queries and Finish() report that one.
TEST(Args, TheFirstFailureIsKept) {
  Args a({"--start", "x", "--name"}, &kSpec);
  ASSERT_FALSE(a.status().ok());  // --name needs a value: found when the words are classified
  EXPECT_EQ(a.status().error().message, "option --name needs a value (NAME)");
  Args b({"--start", "x"}, &kSpec);
  EXPECT_FALSE(b.Number("--start").has_value());
  EXPECT_EQ(b.Required("--name"), "");
  const Outcome r = b.Finish();
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "option --start: \"x\" is not a number");
}

TEST(Args, AskingForAnUndeclaredOptionIsAProgrammingError) {
  for (int k = 0; k < 3; ++k) {
    Args a({}, &kSpec);
    if (k == 0) a.Value("--nope");
    if (k == 1) a.Flag("--name");   // declared with a value
    if (k == 2) a.Value("--json");  // declared as a flag
    const Outcome r = a.Finish();
    ASSERT_FALSE(r.ok()) << k;
    EXPECT_EQ(r.error().code, Error::kInvalidArgument) << k;
  }
}

}  // namespace
}  // namespace volcomp::args
