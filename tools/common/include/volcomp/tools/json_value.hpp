// A JSON document in memory: what a command reports (built by the command, printed by the
// command layer as JSON or through the command's text layout) and what the tool reads back (e.g.
// `volcomp report compare` reading the results `evaluate ... --report DIR` wrote).
//
//   JsonValue r = JsonValue::Object();
//   r.Set("file", path).Set("image_size", uint64_t{size});
//   JsonValue& axes = r.Set("axes", JsonValue::Array())["axes"];
//   WriteJson(r, std::cout);
//
// Numbers keep whether they were written as integers (printed exactly, also beyond 2^53) or as
// doubles (printed as the shortest decimal that round-trips; NaN/Inf as null). Members keep their
// order. ParseJson reads objects, arrays, strings with escapes (\uXXXX to UTF-8, surrogate pairs),
// numbers, true, false, null; its failures say "source: line L: problem".
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::tools {

struct JsonValue {
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };
  Type type = Type::kNull;
  bool boolean = false;
  double number = 0.0;
  bool is_int = false;       // a number written as an integer: `integer` holds it exactly
  bool is_unsigned = false;  // ... and it is above INT64_MAX (`uinteger` holds it)
  int64_t integer = 0;
  uint64_t uinteger = 0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  // in document order

  JsonValue() = default;            // null
  JsonValue(bool b);                // NOLINT: implicit, so Set("ok", true) reads naturally
  JsonValue(int v);                 // NOLINT
  JsonValue(unsigned v);            // NOLINT
  JsonValue(long v);                // NOLINT
  JsonValue(unsigned long v);       // NOLINT
  JsonValue(long long v);           // NOLINT
  JsonValue(unsigned long long v);  // NOLINT
  JsonValue(double v);              // NOLINT
  JsonValue(std::string s);         // NOLINT
  JsonValue(const char* s);         // NOLINT
  static JsonValue Object();
  static JsonValue Array();
  /// An array of the numbers `values`, in order.
  static JsonValue Numbers(const std::vector<double>& values);

  /// Object: sets member `key` (replacing one of that name, else appending); returns *this.
  JsonValue& Set(const std::string& key, JsonValue v);
  /// Array: appends `v`; returns *this.
  JsonValue& Push(JsonValue v);
  /// Object: member `key`, appended as null when absent.
  JsonValue& operator[](const std::string& key);
  /// Array: the last element (after Push).
  JsonValue& back() { return array.back(); }

  /// Member `key` of an object, or nullptr (also for non-objects).
  const JsonValue* get(const std::string& key) const;
  bool is_null() const { return type == Type::kNull; }
  bool is_bool() const { return type == Type::kBool; }
  bool is_number() const { return type == Type::kNumber; }
  bool is_string() const { return type == Type::kString; }
  bool is_object() const { return type == Type::kObject; }
  bool is_array() const { return type == Type::kArray; }
};

/// Parses one JSON document (trailing white space allowed); `source` names it in failures
/// (kInputInvalid).
Expected<JsonValue> ParseJson(const std::string& text, const std::string& source);

/// Writes `v` as JSON: indented with two spaces, or on one line with `compact`.
void WriteJson(const JsonValue& v, std::ostream& out, bool compact = false);

}  // namespace volcomp::tools
