// The INI reader and writer: syntax, comments, case, every structural refusal with its line, the
// value checks' messages, and the writer's layout.
#include "volcomp/hosted/ini.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::hosted {
namespace {

std::string Refusal(const std::string& text) {
  const IniExpected<IniDocument> r = IniDocument::Parse(text, "t.ini");
  return r.ok() ? "" : r.error().ToString();
}

TEST(Ini, SectionsEntriesCommentsAndCase) {
  const IniExpected<IniDocument> r = IniDocument::Parse(
      "; a comment line\n"
      "# another\n"
      "[Board]\n"
      "Node_ID = 0x11   ; hex\n"
      "name = a#b c  # '#' not after a space: kept\n"
      "\n"
      "[axis x]\n"
      "kind=rotary\n",
      "t.ini");
  ASSERT_TRUE(r.ok()) << r.error().ToString();
  const IniDocument& doc = *r;
  ASSERT_EQ(doc.sections().size(), 2u);
  const IniSection* board = doc.Find("board");
  ASSERT_NE(board, nullptr);
  EXPECT_EQ(board->line, 3);
  ASSERT_NE(board->Find("node_id"), nullptr);
  EXPECT_EQ(board->Find("node_id")->value, "0x11");
  EXPECT_EQ(board->Find("node_id")->line, 4);
  EXPECT_EQ(board->Find("name")->value, "a#b c");
  const IniSection* axis = doc.Find("axis", "X");  // arguments compare case-insensitively
  ASSERT_NE(axis, nullptr);
  EXPECT_EQ(axis->Title(), "[axis x]");
  EXPECT_EQ(axis->Find("kind")->value, "rotary");
}

TEST(Ini, StructuralMistakesAreNamedWithTheirLine) {
  EXPECT_EQ(Refusal("[board\n"), "t.ini:1: expected [section]");
  EXPECT_EQ(Refusal("[a b c]\n"), "t.ini:1: bad section header [a b c]");
  EXPECT_EQ(Refusal("[board]\nnode_id\n"), "t.ini:2: expected key = value, got 'node_id'");
  EXPECT_EQ(Refusal("node_id = 1\n"), "t.ini:1: key outside a [section]");
  EXPECT_EQ(Refusal("[board]\nnode_id = 1\nNODE_ID = 2\n"),
            "t.ini:3: node_id: given twice (first at line 2)");
  EXPECT_EQ(Refusal("[axis Z]\n[board]\n[axis z]\n"),
            "t.ini:3: section [axis z] appears twice (first at line 1)");
  const IniExpected<IniDocument> doc = IniDocument::Parse("[board]\n[boards]\n[axis]\n", "t.ini");
  ASSERT_TRUE(doc.ok());
  const IniOutcome sections = doc->CheckSections({"board", "axis NAME", "can"});
  ASSERT_FALSE(sections.ok());
  EXPECT_EQ(sections.error().ToString(),
            "t.ini:2: unknown section [boards] (expected [board], [axis NAME] or [can])");
  const IniExpected<IniDocument> axis = IniDocument::Parse("[axis]\n", "t.ini");
  EXPECT_EQ(axis->CheckSections({"board", "axis NAME"}).error().ToString(),
            "t.ini:1: unknown section [axis] (expected [board] or [axis NAME])");
  const IniExpected<IniDocument> missing = IniDocument::ReadFile("/nonexistent-dir/x.ini");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().ToString(),
            "/nonexistent-dir/x.ini: cannot read the configuration file");
  EXPECT_EQ(missing.error().ToFailure().code, Error::kIoError);
}

TEST(Ini, ValuesAreCheckedAndTheRefusalNamesTheKey) {
  const IniExpected<IniDocument> r = IniDocument::Parse(
      "[v]\na = 0x7FF\nb = -5\nc = 12x\nd = 200\ne = 99999999999999\nf = 0.0005\ng = 1.0000000001\n"
      "h = Yes\ni = maybe\nj = Latest\nk = sometimes\nl =\nm = -20.5\n",
      "t.ini");
  ASSERT_TRUE(r.ok());
  const IniDocument& doc = *r;
  const IniSection& v = doc.sections()[0];
  const auto at = [&](const char* key) { return *v.Find(key); };
  EXPECT_EQ(*ReadInteger(doc, at("a"), 1, 0x7FF), 0x7FF);
  EXPECT_EQ(*ReadInteger(doc, at("b"), -10, 10), -5);
  EXPECT_EQ(ReadInteger(doc, at("b"), 0, 10).error().ToString(),
            "t.ini:3: b = -5: below the lowest value 0");
  EXPECT_EQ(ReadInteger(doc, at("c"), 0, 10).error().ToString(),
            "t.ini:4: c: expected a number, got '12x'");
  EXPECT_EQ(ReadInteger(doc, at("d"), 1, 127, " of 2000:1 (Node-ID)").error().message,
            "d = 200: above the highest value 127 of 2000:1 (Node-ID)");
  EXPECT_EQ(ReadInteger(doc, at("e"), 0, 10).error().message, "e: 99999999999999 is out of range");
  EXPECT_EQ(ReadInteger(doc, at("l"), 0, 10).error().message, "l: expected a number, got ''");
  EXPECT_EQ(*ReadDecimalE9(doc, at("f"), 1, 0xFFFFFFFF), 500000);
  EXPECT_EQ(ReadDecimalE9(doc, at("g"), 1, 0xFFFFFFFF).error().message,
            "g: expected a decimal with at most 9 decimals, got '1.0000000001'");
  EXPECT_EQ(ReadDecimalE9(doc, at("f"), 1000000, 0xFFFFFFFF).error().message,
            "f = 0.0005: below the lowest value 1000000 (x 1e-9)");
  // Two decimals, negative: -20.5 is -2050 hundredths.
  EXPECT_EQ(*ReadDecimal(doc, at("m"), 2, -32767, 32767), -2050);
  EXPECT_EQ(ReadDecimal(doc, at("m"), 2, -2000, 9000).error().message,
            "m = -20.5: below the lowest value -2000 (x 1e-2)");
  EXPECT_EQ(ReadDecimal(doc, at("f"), 2, -2000, 9000).error().message,
            "f: expected a decimal with at most 2 decimals, got '0.0005'");
  EXPECT_TRUE(*ReadBool(doc, at("h")));
  EXPECT_EQ(ReadBool(doc, at("i")).error().message, "i: expected true or false, got 'maybe'");
  EXPECT_EQ(*ReadChoice(doc, at("j"), {"sync", "latest"}), 1u);
  EXPECT_EQ(ReadChoice(doc, at("k"), {"sync", "latest"}).error().message,
            "k: expected sync | latest, got 'sometimes'");
}

TEST(Ini, UnknownKeysListTheKnownOnes) {
  const IniExpected<IniDocument> r =
      IniDocument::Parse("[can]\ncontroller = a\nbogus = 1\n", "t.ini");
  ASSERT_TRUE(r.ok());
  std::string controller;
  const IniOutcome o = ReadKeys(*r, r->Find("can"),
                                {{"controller",
                                  [&](const IniEntry& e) -> IniOutcome {
                                    controller = e.value;
                                    return IniOutcome::Ok();
                                  }},
                                 {"drives", [](const IniEntry&) { return IniOutcome::Ok(); }}});
  ASSERT_FALSE(o.ok());
  EXPECT_EQ(controller, "a");  // in file order, up to the mistake
  EXPECT_EQ(o.error().ToString(),
            "t.ini:3: unknown key 'bogus' in [can] (known: controller, drives)");
  EXPECT_TRUE(ReadKeys(*r, nullptr, {}).ok());  // a section left out: nothing to read
}

TEST(Ini, TheWriterAlignsCommentsAndSeparatesSections) {
  IniWriter w;
  w.Comment("header");
  w.Section("board");
  w.Key("node_id", "16", "2000:1 CAN node-ID, 1..127");
  w.Key("a_very_long_key_name_beyond_the_column", "1", "note");
  w.Key("plain", "yes");
  w.Section("axis X");
  EXPECT_EQ(w.text(),
            "# header\n"
            "\n"
            "[board]\n"
            "node_id = 16                     # 2000:1 CAN node-ID, 1..127\n"
            "a_very_long_key_name_beyond_the_column = 1 # note\n"
            "plain = yes\n"
            "\n"
            "[axis X]\n");
  IniWriter first;
  first.Section("board");
  EXPECT_EQ(first.text(), "[board]\n");
  EXPECT_EQ(FormatDecimalE9(500000), "0.0005");
  EXPECT_EQ(FormatDecimalE9(2000000000), "2");
  EXPECT_EQ(FormatDecimalE9(1), "0.000000001");
  EXPECT_EQ(FormatHex(0x80, 3), "0x080");
}

}  // namespace
}  // namespace volcomp::hosted
