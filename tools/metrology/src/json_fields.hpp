// Reading back the JSON documents the report writers build (the text layouts print from them):
// members are looked up by key; a missing member reads as null, 0 or "".
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/tools/json_value.hpp"

namespace volcomp::metrology::json {

using tools::JsonValue;

/// Member `key` of `object`, or a null value.
inline const JsonValue& At(const JsonValue& object, const std::string& key) {
  static const JsonValue kNull;
  const JsonValue* v = object.get(key);
  return v != nullptr ? *v : kNull;
}
inline double Number(const JsonValue& object, const std::string& key) {
  return At(object, key).number;
}
inline int64_t Integer(const JsonValue& object, const std::string& key) {
  return At(object, key).integer;
}
inline const std::string& Text(const JsonValue& object, const std::string& key) {
  return At(object, key).string;
}

}  // namespace volcomp::metrology::json
