// Minimal JSON reader for the tool's own JSON outputs (e.g. `volcomp report compare` reading the
// results `evaluate ... --report DIR` wrote): objects, arrays, strings with escapes (\uXXXX to
// UTF-8, surrogate pairs), numbers, true, false, null. Errors are tools::InputError
// "source: line L: problem".
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace volcomp::tools {

struct JsonValue {
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };
  Type type = Type::kNull;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  // in document order

  /// Member `key` of an object, or nullptr (also for non-objects).
  const JsonValue* get(const std::string& key) const;
  bool is_number() const { return type == Type::kNumber; }
  bool is_string() const { return type == Type::kString; }
  bool is_object() const { return type == Type::kObject; }
  bool is_array() const { return type == Type::kArray; }
};

/// Parses one JSON document (trailing white space allowed); `source` names it in errors.
JsonValue ParseJson(const std::string& text, const std::string& source);

}  // namespace volcomp::tools
