// `volcomp reproduce` run as main() runs it: all seeds (the CI run of every reproduction), one
// seed and one table, the JSON's counts against the text's summary, and the refusals.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cli_runner.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;

int Int(const tools::JsonValue& object, const char* key) {
  const tools::JsonValue* v = object.get(key);
  return v != nullptr && v->is_number() ? static_cast<int>(v->number) : -1;
}

// The text's total line as the JSON's summary says it.
std::string TotalLine(const tools::JsonValue& s) {
  char text[200];
  std::snprintf(text, sizeof text,
                "total: %d values reproduced, %d known misprints, %d mismatches; %d tables not "
                "reproducible (listed)\n",
                Int(s, "reproduced"), Int(s, "misprints"), Int(s, "mismatches"),
                Int(s, "not_reproducible"));
  return text;
}

TEST(ReproduceCli, AllSeedsReproduceWithoutMismatch) {
  const auto json = RunCli({"reproduce", "--json"});
  ASSERT_EQ(json.code, 0) << json.err << json.out.substr(0, 2000);
  const tools::JsonValue data = tools::ParseJson(json.out, "reproduce --json").value();
  const tools::JsonValue& summary = *data.get("summary");
  EXPECT_EQ(Int(summary, "mismatches"), 0);
  EXPECT_GT(Int(summary, "reproduced"), 0);
  EXPECT_GT(Int(summary, "misprints"), 0);
  EXPECT_GT(Int(summary, "not_reproducible"), 0);
  // Every cell listed carries a verdict other than mismatch; the counts add up.
  int cells = 0;
  for (const tools::JsonValue& t : data.get("tables")->array) {
    for (const tools::JsonValue& c : t.get("cells")->array) {
      ++cells;
      EXPECT_NE(c.get("verdict")->string, "mismatch") << c.get("row")->string;
    }
  }
  EXPECT_EQ(cells, Int(summary, "reproduced") + Int(summary, "misprints"));
  EXPECT_EQ(static_cast<int>(data.get("not_reproduced")->array.size()),
            Int(summary, "not_reproducible"));
  EXPECT_EQ(static_cast<int>(data.get("seeds")->array.size()), 4);

  const auto text = RunCli({"reproduce"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find(TotalLine(summary)), std::string::npos) << TotalLine(summary);
}

TEST(ReproduceCli, GostSeedShowsTheKnownMisprintWithItsFootnote) {
  const auto r = RunCli({"reproduce", "--seed", "gost27843"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("results | R↓ | 9.92 µm | 9.892 | -0.028 | misprint ["), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("results, R↓: printed 9,92"), std::string::npos);
  EXPECT_NE(r.out.find("gost27843: 1 tables; "), std::string::npos);
  EXPECT_EQ(r.out.find("iso230-7"), std::string::npos);
}

TEST(ReproduceCli, OneTableAndDifferencesOnly) {
  const auto r = RunCli(
      {"reproduce", "--seed", "gost27843", "--table", "example", "--mismatches-only", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue data = tools::ParseJson(r.out, "reproduce --json").value();
  const auto& tables = data.get("tables")->array;
  ASSERT_EQ(tables.size(), 1u);
  // Only the misprints are listed; the counts still cover the whole table.
  for (const tools::JsonValue& c : tables[0].get("cells")->array) {
    EXPECT_EQ(c.get("verdict")->string, "misprint");
  }
  EXPECT_EQ(static_cast<int>(tables[0].get("cells")->array.size()),
            Int(*data.get("summary"), "misprints"));
  EXPECT_GT(Int(*data.get("summary"), "reproduced"), 0);
}

TEST(ReproduceCli, UnknownSeedOrTableIsAUsageError) {
  auto r = RunCli({"reproduce", "--seed", "nonsense"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("unknown seed 'nonsense'; known seeds: gost27843, iso230-6, iso230-7, "
                       "dissertation"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty());
  r = RunCli({"reproduce", "--seed", "gost27843", "--table", "7.7"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("unknown table '7.7'"), std::string::npos) << r.err;
  r = RunCli({"reproduce", "extra"});
  EXPECT_EQ(r.code, tools::kExitUsage);
}

}  // namespace
}  // namespace volcomp
