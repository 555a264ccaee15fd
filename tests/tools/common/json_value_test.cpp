// JSON documents: reading (values, escapes, the writer's output read back, errors with their
// line), building and writing (integers exact, member order, compact form).
#include "volcomp/tools/json_value.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

TEST(JsonReader, ValuesAndEscapes) {
  const auto parsed = ParseJson(
      " {\"a\": [1, -2.5e3, true, false, null], \"s\": \"q\\\"\\\\\\/\\n\\u00b5m \\ud83d\\ude00\","
      " \"o\": {}} \n",
      "t.json");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  const JsonValue& v = *parsed;
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
  const auto parsed = ParseJson(s.str(), "w.json");
  ASSERT_TRUE(parsed.ok());
  const JsonValue& v = *parsed;
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
    const auto r = ParseJson(text, "bad.json");
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().code, Error::kInputInvalid);
    EXPECT_EQ(r.error().message, message);
  }
}

TEST(JsonValue, BuiltDocumentsWriteInOrderWithExactIntegers) {
  JsonValue doc = JsonValue::Object();
  doc.Set("name", "x").Set("crc", uint64_t{0xFFFFFFFFFFFFFFFFull}).Set("n", -3);
  doc["list"].Push(1.5).Push(true).Push(JsonValue());
  doc.Set("name", "y");  // replaces, keeps the place
  std::ostringstream pretty, compact;
  WriteJson(doc, pretty);
  WriteJson(doc, compact, true);
  EXPECT_EQ(compact.str(),
            "{\"name\": \"y\", \"crc\": 18446744073709551615, \"n\": -3, "
            "\"list\": [1.5, true, null]}\n");
  EXPECT_EQ(pretty.str(),
            "{\n  \"name\": \"y\",\n  \"crc\": 18446744073709551615,\n  \"n\": -3,\n"
            "  \"list\": [\n    1.5,\n    true,\n    null\n  ]\n}\n");
  // Read back: integers stay exact beyond 2^53.
  const auto back = ParseJson(pretty.str(), "doc.json");
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(back->get("crc")->is_unsigned);
  EXPECT_EQ(back->get("crc")->uinteger, 0xFFFFFFFFFFFFFFFFull);
  EXPECT_EQ(back->get("n")->integer, -3);
  EXPECT_FALSE(back->get("list")->array[0].is_int);
}

TEST(JsonValue, AnArrayOfNumbers) {
  std::ostringstream out;
  WriteJson(JsonValue::Numbers({1.5, -2, 0.1}), out, true);
  EXPECT_EQ(out.str(), "[1.5, -2, 0.1]\n");
  EXPECT_TRUE(JsonValue::Numbers({}).is_array());
}

}  // namespace
}  // namespace volcomp::tools
