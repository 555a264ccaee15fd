// JSON reader: values, escapes, the writer's output read back, errors with their line.
#include "volcomp/tools/json_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

TEST(JsonReader, ValuesAndEscapes) {
  const JsonValue v = ParseJson(
      " {\"a\": [1, -2.5e3, true, false, null], \"s\": \"q\\\"\\\\\\/\\n\\u00b5m \\ud83d\\ude00\","
      " \"o\": {}} \n",
      "t.json");
  ASSERT_TRUE(v.is_object());
  const JsonValue* a = v.get("a");
  ASSERT_TRUE(a && a->is_array());
  ASSERT_EQ(a->array.size(), 5u);
  EXPECT_EQ(a->array[0].number, 1.0);
  EXPECT_EQ(a->array[1].number, -2500.0);
  EXPECT_TRUE(a->array[2].boolean);
  EXPECT_EQ(a->array[3].type, JsonValue::Type::kBool);
  EXPECT_FALSE(a->array[3].boolean);
  EXPECT_EQ(a->array[4].type, JsonValue::Type::kNull);
  EXPECT_EQ(v.get("s")->string, "q\"\\/\n\xC2\xB5m \xF0\x9F\x98\x80");
  EXPECT_TRUE(v.get("o")->is_object());
  EXPECT_EQ(v.get("missing"), nullptr);
}

TEST(JsonReader, ReadsWhatTheWriterWrites) {
  std::ostringstream s;
  {
    JsonWriter w(s);
    w.begin_object();
    w.key("name").value("A↑ \"x\"");
    w.key("v").value(0.1 + 0.2);
    w.key("list").begin_array();
    w.value(int64_t{-7});
    w.null();
    w.end_array();
    w.end_object();
  }
  const JsonValue v = ParseJson(s.str(), "w.json");
  EXPECT_EQ(v.get("name")->string, "A↑ \"x\"");
  EXPECT_EQ(v.get("v")->number, 0.1 + 0.2);
  EXPECT_EQ(v.get("list")->array[0].number, -7.0);
}

TEST(JsonReader, ErrorsNameTheLine) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"{\n\"a\": 1,\n}", "bad.json: line 3: expected a member name"},
           {"[1 2]", "bad.json: line 1: expected ',' or ']'"},
           {"{\"a\": \"x}", "bad.json: line 1: unterminated string"},
           {"[1]\n x", "bad.json: line 2: unexpected text after the document"},
           {"", "bad.json: line 1: unexpected end of input"}}) {
    try {
      ParseJson(text, "bad.json");
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}

}  // namespace
}  // namespace volcomp::tools
