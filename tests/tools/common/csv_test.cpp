// CSV reader: syntax, and error messages that name the line and the problem.
#include "volcomp/tools/csv.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"

namespace volcomp::tools {
namespace {

using testing::ValueOf;

CsvTable Parse(const std::string& text, const std::string& source = "<string>") {
  return ValueOf(CsvTable::ReadString(text, source));
}

double Num(const CsvRow& row, const std::string& column) { return ValueOf(row.Number(column)); }

// The message of the first failure reading `text` (and `column` of every row), "" when none.
std::string ErrorOf(const std::string& text, const std::string& column = "") {
  const Expected<CsvTable> t = CsvTable::ReadString(text, "in.csv");
  if (!t.ok()) return t.error().message;
  for (const CsvRow& r : t->rows()) {
    if (column.empty()) continue;
    const Expected<double> v = r.Number(column);
    if (!v.ok()) {
      EXPECT_EQ(v.error().code, Error::kInputInvalid);
      return v.error().message;
    }
  }
  return "";
}

TEST(Csv, ParsesQuotesCommentsSeparatorsAndCrlf) {
  const CsvTable t = Parse(
      "\xEF\xBB\xBF# comment\r\nname;value\r\n\r\n\"a;b\";1.5\r\n\"say \"\"hi\"\"\"; -2e3 \r\n");
  ASSERT_EQ(t.header().size(), 2u);
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(ValueOf(t.rows()[0].Text("name")), "a;b");
  EXPECT_EQ(ValueOf(t.rows()[1].Text("name")), "say \"hi\"");
  EXPECT_DOUBLE_EQ(Num(t.rows()[1], "value"), -2000);
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

// What Excel writes when a sheet has a wider row somewhere: every row padded with separators,
// empty rows as separators only.
TEST(Csv, SpreadsheetPaddingAndEmptyRowsAreSkipped) {
  const CsvTable t = Parse(";;;;\naxis;target_mm;dev_um;;\nX;0;1,5;;\n;;;;\nX;10;-2;;\n;;;;\n");
  ASSERT_EQ(t.header().size(), 3u);
  EXPECT_EQ(t.header()[2], "dev_um");
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_DOUBLE_EQ(Num(t.rows()[0], "dev_um"), 1.5);
  EXPECT_DOUBLE_EQ(Num(t.rows()[1], "target_mm"), 10);
  EXPECT_EQ(t.rows()[1].line(), 5u);
  // A cell beyond the header is data, not padding.
  EXPECT_EQ(ErrorOf("a;b;;\n1;2;;\n1;2;3;\n"), "in.csv:3: expected 2 fields, found 3");
  // An empty name between two columns is still an error.
  EXPECT_EQ(ErrorOf("a;;b\n1;2;3\n"), "in.csv:1: empty column name in header");
}

TEST(Csv, ATitleRowAboveTheHeaderIsNamedAsSuch) {
  EXPECT_EQ(ErrorOf("Positioning test X;;;\naxis;target_mm;dev_um;\nX;0;1\n"),
            "in.csv:1: \"Positioning test X\" looks like a title row (one cell, the rest of the "
            "row empty), not the header: delete it or start it with #");
  // A single-column file is not a title row.
  EXPECT_EQ(Parse("x_mm\n4\n").rows().size(), 1u);
}

TEST(Csv, RowsOutliveTheTable) {
  std::vector<CsvRow> rows;
  {
    const CsvTable t = Parse("x\n4\n");
    rows = t.rows();
  }
  EXPECT_EQ(Num(rows[0], "x"), 4);
}

TEST(Csv, DecimalCommaInSemicolonAndTabFiles) {
  for (const char* sep : {";", "\t"}) {
    const std::string s = sep;
    const CsvTable t = Parse(
        "target_mm" + s + "deviation_um\n150,71" + s + "-2,6\n0" + s + "1e-1\n-,5" + s + "1,5e2\n",
        "eu.csv");
    EXPECT_TRUE(t.decimal_comma());
    EXPECT_DOUBLE_EQ(Num(t.rows()[0], "target_mm"), 150.71);
    EXPECT_DOUBLE_EQ(Num(t.rows()[0], "deviation_um"), -2.6);
    EXPECT_DOUBLE_EQ(Num(t.rows()[1], "deviation_um"), 0.1);
    EXPECT_DOUBLE_EQ(Num(t.rows()[2], "target_mm"), -0.5);
    EXPECT_DOUBLE_EQ(Num(t.rows()[2], "deviation_um"), 150);
  }
  // The same separators with decimal points.
  const CsvTable p = Parse("a;b\n1.5;2\n", "p.csv");
  EXPECT_FALSE(p.decimal_comma());
  EXPECT_DOUBLE_EQ(Num(p.rows()[0], "a"), 1.5);
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
  const CsvTable t = Parse(
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

// The reader scans each field once: a field of 100 000 digits with a decimal comma (which crashed
// the regex-based reader of before with a stack overflow) reads in linear time and stack.
TEST(Csv, AHugeFieldIsReadWithoutRecursion) {
  const std::string digits(100000, '7');
  const CsvTable t = Parse("a;b\n1," + digits + ";2\n", "huge.csv");
  EXPECT_TRUE(t.decimal_comma());
  EXPECT_DOUBLE_EQ(Num(t.rows()[0], "b"), 2);
  EXPECT_NE(ErrorOf("a;b\n1;" + digits + "x\n", "b").find("is not a number"), std::string::npos);
  const CsvTable p = Parse("# " + std::string(100000, 'k') + ": v\nx\n1\n");
  ASSERT_EQ(p.preamble().size(), 1u);  // one long word is a key (letters, digits, '_')
  EXPECT_EQ(p.preamble()[0].key.size(), 100000u);
  EXPECT_EQ(p.preamble()[0].value, "v");
}

// Issue 27 item 6: quote characters inside an unquoted field and very wide headers were
// quadratic (a copy of the field per quote, every column name compared with every other).
TEST(Csv, QuotesAndWideHeadersAreReadInOnePass) {
  const std::string word(50000, 'a'), quotes(50000, '"');
  const CsvTable q = Parse("name,v\n" + word + quotes + ",1\n");
  EXPECT_EQ(ValueOf(q.rows()[0].Text("name")), word + quotes);  // kept as written
  const CsvTable after = Parse("name,v\r\n\"ab\"cd,1\r\nx,\"2\"\r\n");
  EXPECT_EQ(ValueOf(after.rows()[0].Text("name")), "abcd");
  EXPECT_EQ(ValueOf(after.rows()[1].Text("v")), "2");  // no CR kept from a CRLF line
  EXPECT_DOUBLE_EQ(Num(after.rows()[1], "v"), 2);

  std::string header;
  for (int i = 0; i < 20000; ++i) header += "c" + std::to_string(i) + ",";
  EXPECT_NE(ErrorOf(header + "c17,c5\n").find("column \"c17\" appears twice"), std::string::npos);
  EXPECT_NE(ErrorOf("a,b,b,a\n").find("column \"b\" appears twice"), std::string::npos);
  EXPECT_EQ(Parse(header + "last\n").header().size(), 20001u);
}

}  // namespace
}  // namespace volcomp::tools

namespace volcomp::tools {
namespace {

TEST(ParseTriple, ThreeNumbersSeparatedByCommasOrNothing) {
  const auto p = ParseTriple(" 200, -140.5,1e2 ");
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ((*p)[0], 200);
  EXPECT_EQ((*p)[1], -140.5);
  EXPECT_EQ((*p)[2], 100);
  for (const char* bad : {"", "1,2", "1,2,3,4", "1,,3", "1,2,x", "1;2;3"}) {
    EXPECT_FALSE(ParseTriple(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace volcomp::tools
