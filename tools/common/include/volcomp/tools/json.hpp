// Minimal JSON writer for `--json` outputs (objects, arrays, strings, numbers, booleans, null).
//
// JsonWriter w(std::cout); w.begin_object(); w.key("a").value(1.5); w.end_object();
// Output is indented with two spaces (or on one line: JsonWriter(out, true)); doubles are printed
// with up to 17 significant digits (shortest round-trip form where possible), NaN/Inf as null.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace volcomp::tools {

struct JsonValue;

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out, bool compact = false) : out_(out), compact_(compact) {}
  ~JsonWriter();

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  /// Inside an object: the key of the next value.
  JsonWriter& key(const std::string& k);
  JsonWriter& value(const std::string& s);
  JsonWriter& value(const char* s) { return value(std::string(s)); }
  JsonWriter& value(double d);
  JsonWriter& value(int64_t i);
  JsonWriter& value(uint64_t u);
  JsonWriter& value(int i) { return value(static_cast<int64_t>(i)); }
  JsonWriter& value(unsigned u) { return value(static_cast<uint64_t>(u)); }
  JsonWriter& value(bool b);
  /// A whole document value (objects and arrays recursively).
  JsonWriter& value(const JsonValue& v);
  JsonWriter& null();

  /// Escapes a string for JSON (without the surrounding quotes).
  static std::string Escape(const std::string& s);
  /// Formats a double as the shortest decimal that round-trips.
  static std::string FormatDouble(double d);

 private:
  void BeforeValue();
  JsonWriter& End(char close);
  void Newline();
  std::ostream& out_;
  bool compact_ = false;
  std::vector<bool> first_;  // per open container: no element written yet
  bool after_key_ = false;
};

}  // namespace volcomp::tools
