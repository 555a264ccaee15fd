// CSV reader: syntax, and error messages that name the line and the problem.
#include "volcomp/tools/csv.hpp"

#include <gtest/gtest.h>

namespace volcomp::tools {
namespace {

std::string ErrorOf(const std::string& text, const std::string& column = "") {
  try {
    const CsvTable t = CsvTable::ParseString(text, "in.csv");
    for (const CsvRow& r : t.rows()) {
      if (!column.empty()) r.number(column);
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Csv, ParsesQuotesCommentsSeparatorsAndCrlf) {
  const CsvTable t = CsvTable::ParseString(
      "\xEF\xBB\xBF# comment\r\nname;value\r\n\r\n\"a;b\";1.5\r\n\"say \"\"hi\"\"\"; -2e3 \r\n");
  ASSERT_EQ(t.header().size(), 2u);
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[0].text("name"), "a;b");
  EXPECT_EQ(t.rows()[1].text("name"), "say \"hi\"");
  EXPECT_DOUBLE_EQ(t.rows()[1].number("value"), -2000);
  EXPECT_EQ(t.rows()[1].line(), 5u);
}

TEST(Csv, ErrorsNameLineAndProblem) {
  EXPECT_EQ(ErrorOf(""), "in.csv: no header line (empty input)");
  EXPECT_EQ(ErrorOf("a,b\n1,2\n3\n"), "in.csv:3: expected 2 fields, found 1");
  EXPECT_EQ(ErrorOf("a,b\n1,x\n", "b"), "in.csv:2: column \"b\": \"x\" is not a number");
  EXPECT_EQ(ErrorOf("a,b\n1,2\n", "c"), "in.csv:1: missing column \"c\"");
  EXPECT_EQ(ErrorOf("a,a\n"), "in.csv:1: column \"a\" appears twice in header");
  EXPECT_EQ(ErrorOf("a,b\n1,\"2\n"), "in.csv:2: unterminated quote");
  EXPECT_EQ(ErrorOf("a,b\n1,nan\n", "b"), "in.csv:2: column \"b\": \"nan\" is not a number");
  EXPECT_EQ(ErrorOf("a,b\n1,1e999\n", "b"), "in.csv:2: column \"b\": \"1e999\" is not a number");
}

TEST(Csv, RowsOutliveTheTable) {
  std::vector<CsvRow> rows;
  {
    const CsvTable t = CsvTable::ParseString("x\n4\n");
    rows = t.rows();
  }
  EXPECT_EQ(rows[0].number("x"), 4);
}

}  // namespace
}  // namespace volcomp::tools
