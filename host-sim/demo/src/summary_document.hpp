// Reading the demo's summary document (SummaryData) back where it is printed: the document is
// ours, so a missing member is null and reads as 0.
#pragma once

#include <cstddef>
#include <string>

#include "volcomp/tools/json_value.hpp"

namespace volcomp::sim::summary_document {

inline const tools::JsonValue& At(const tools::JsonValue& v, const std::string& key) {
  static const tools::JsonValue kNull;
  const tools::JsonValue* m = v.get(key);
  return m != nullptr ? *m : kNull;
}
inline double Num(const tools::JsonValue& v, const std::string& key) { return At(v, key).number; }
inline double Num(const tools::JsonValue& v, const std::string& key, size_t i) {
  const tools::JsonValue& a = At(v, key);
  return i < a.array.size() ? a.array[i].number : 0.0;
}

}  // namespace volcomp::sim::summary_document
