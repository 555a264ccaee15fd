// Minimal JSON writer.
#include "volcomp/tools/json.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "volcomp/tools/json_value.hpp"

namespace volcomp::tools {

JsonWriter::~JsonWriter() {
  if (first_.empty()) out_ << "\n";
}

void JsonWriter::Newline() {
  if (compact_) return;
  out_ << "\n";
  for (std::size_t i = 0; i < first_.size(); ++i) out_ << "  ";
}

void JsonWriter::BeforeValue() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back()) out_ << (compact_ ? ", " : ",");
    first_.back() = false;
    Newline();
  }
}

JsonWriter& JsonWriter::begin_object() {
  BeforeValue();
  out_ << "{";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::End(char close) {
  const bool empty = first_.back();
  first_.pop_back();
  if (!empty) Newline();
  out_ << close;
  return *this;
}

JsonWriter& JsonWriter::end_object() { return End('}'); }

JsonWriter& JsonWriter::begin_array() {
  BeforeValue();
  out_ << "[";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_array() { return End(']'); }

JsonWriter& JsonWriter::key(const std::string& k) {
  BeforeValue();
  out_ << "\"" << Escape(k) << "\": ";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& s) {
  BeforeValue();
  out_ << "\"" << Escape(s) << "\"";
  return *this;
}

JsonWriter& JsonWriter::value(double d) {
  BeforeValue();
  out_ << FormatDouble(d);
  return *this;
}

JsonWriter& JsonWriter::value(int64_t i) {
  BeforeValue();
  out_ << i;
  return *this;
}

JsonWriter& JsonWriter::value(uint64_t u) {
  BeforeValue();
  out_ << u;
  return *this;
}

JsonWriter& JsonWriter::value(bool b) {
  BeforeValue();
  out_ << (b ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::value(const JsonValue& v) {
  switch (v.type) {
    case JsonValue::Type::kNull:
      return null();
    case JsonValue::Type::kBool:
      return value(v.boolean);
    case JsonValue::Type::kNumber:
      if (v.is_unsigned) return value(static_cast<uint64_t>(v.uinteger));
      if (v.is_int) return value(static_cast<int64_t>(v.integer));
      return value(v.number);
    case JsonValue::Type::kString:
      return value(v.string);
    case JsonValue::Type::kArray:
      begin_array();
      for (const JsonValue& e : v.array) value(e);
      return end_array();
    case JsonValue::Type::kObject:
      begin_object();
      for (const auto& [k, e] : v.object) key(k).value(e);
      return end_object();
  }
  return *this;
}

JsonWriter& JsonWriter::null() {
  BeforeValue();
  out_ << "null";
  return *this;
}

std::string JsonWriter::Escape(const std::string& s) {
  std::string o;
  for (unsigned char c : s) {
    switch (c) {
      case '"':
        o += "\\\"";
        break;
      case '\\':
        o += "\\\\";
        break;
      case '\n':
        o += "\\n";
        break;
      case '\r':
        o += "\\r";
        break;
      case '\t':
        o += "\\t";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          o += buf;
        } else {
          o += static_cast<char>(c);
        }
    }
  }
  return o;
}

std::string JsonWriter::FormatDouble(double d) {
  if (!std::isfinite(d)) return "null";
  char buf[32];
  // A whole number below 1e15 in full (200, not the shortest round trip "2e+02").
  if (std::fabs(d) < 1e15 && std::trunc(d) == d) {
    std::snprintf(buf, sizeof buf, "%.0f", d);
    return buf;
  }
  for (int prec = 1; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, d);
    if (std::strtod(buf, nullptr) == d) break;
  }
  return buf;
}

}  // namespace volcomp::tools
