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

TEST(Csv, DecimalCommaInSemicolonAndTabFiles) {
  for (const char* sep : {";", "\t"}) {
    const std::string s = sep;
    const CsvTable t = CsvTable::ParseString(
        "target_mm" + s + "deviation_um\n150,71" + s + "-2,6\n0" + s + "1e-1\n-,5" + s + "1,5e2\n",
        "eu.csv");
    EXPECT_TRUE(t.decimal_comma());
    EXPECT_DOUBLE_EQ(t.rows()[0].number("target_mm"), 150.71);
    EXPECT_DOUBLE_EQ(t.rows()[0].number("deviation_um"), -2.6);
    EXPECT_DOUBLE_EQ(t.rows()[1].number("deviation_um"), 0.1);
    EXPECT_DOUBLE_EQ(t.rows()[2].number("target_mm"), -0.5);
    EXPECT_DOUBLE_EQ(t.rows()[2].number("deviation_um"), 150);
  }
  // The same separators with decimal points.
  const CsvTable p = CsvTable::ParseString("a;b\n1.5;2\n", "p.csv");
  EXPECT_FALSE(p.decimal_comma());
  EXPECT_DOUBLE_EQ(p.rows()[0].number("a"), 1.5);
  // A ',' separated file has decimal points only: "1,5" are two fields.
  EXPECT_EQ(ErrorOf("a,b\n1,5,6\n"), "in.csv:2: expected 2 fields, found 3");
}

TEST(Csv, OneDecimalMarkPerFileAndErrorsNameTheLine) {
  EXPECT_EQ(ErrorOf("a;b\n1,5;2\n3.5;4\n", "a"),
            "in.csv:3: column \"a\": \"3.5\" has a decimal point, but this file writes decimal "
            "commas (line 2); use one decimal mark throughout");
  EXPECT_EQ(ErrorOf("a\tb\n1.5\t2\n3,5\t4\n", "a"),
            "in.csv:3: column \"a\": \"3,5\" has a decimal comma, but this file writes decimal "
            "points (line 2); use one decimal mark throughout");
  EXPECT_EQ(ErrorOf("a;b\n1,5;x\n", "b"), "in.csv:2: column \"b\": \"x\" is not a number");
}

TEST(Csv, PreambleKeyValueLinesBeforeTheHeader) {
  const CsvTable t = CsvTable::ParseString(
      "# positioning test of the X axis\n# machine: MILL-7\n#axis:X\n# air temperature C: "
      "20,4\n# note = not a key\n# GOST 27843-88 example: no key (too long, digits)\nx\n# "
      "after: the header\n1\n");
  ASSERT_EQ(t.preamble().size(), 3u);
  EXPECT_EQ(t.preamble()[0].key, "machine");
  EXPECT_EQ(t.preamble()[0].value, "MILL-7");
  EXPECT_EQ(t.preamble()[0].line, 2u);
  EXPECT_EQ(t.preamble()[1].key, "axis");
  EXPECT_EQ(t.preamble()[1].value, "X");
  EXPECT_EQ(t.preamble()[2].key, "air temperature C");
  EXPECT_EQ(t.preamble()[2].value, "20,4");
}

}  // namespace
}  // namespace volcomp::tools
