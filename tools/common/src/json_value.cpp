// JSON documents in memory: building, reading, writing.
#include "volcomp/tools/json_value.hpp"

#include <cerrno>
#include <cstdlib>

#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

// Recursive descent with a depth limit; the first problem stops the parse (failed_).
class Parser {
 public:
  Parser(const std::string& text, const std::string& source) : s_(text), source_(source) {}

  Expected<JsonValue> Document() {
    JsonValue v = Value(0);
    Space();
    if (!failed_ && i_ != s_.size()) Problem("unexpected text after the document");
    if (failed_) return ::volcomp::Fail(Error::kInputInvalid, message_);
    return v;
  }

 private:
  void Problem(const std::string& what) {
    if (failed_) return;
    std::size_t line = 1;
    for (std::size_t k = 0; k < i_ && k < s_.size(); ++k) line += s_[k] == '\n';
    failed_ = true;
    message_ = source_ + ": line " + std::to_string(line) + ": " + what;
  }

  void Space() {
    while (i_ < s_.size() &&
           (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) {
      ++i_;
    }
  }

  bool Take(const char* word) {
    const std::string w = word;
    if (s_.compare(i_, w.size(), w) != 0) return false;
    i_ += w.size();
    return true;
  }

  JsonValue Value(int depth) {
    JsonValue v;
    if (depth > 200) return Problem("nesting too deep"), v;
    Space();
    if (i_ >= s_.size()) return Problem("unexpected end of input"), v;
    const char c = s_[i_];
    if (c == '{') return Members(depth);
    if (c == '[') return Elements(depth);
    if (c == '"') return JsonValue(String());
    if (Take("true")) return JsonValue(true);
    if (Take("false")) return JsonValue(false);
    if (Take("null")) return v;
    return Number();
  }

  JsonValue Members(int depth) {
    JsonValue v = JsonValue::Object();
    ++i_;
    Space();
    if (i_ < s_.size() && s_[i_] == '}') return ++i_, v;
    while (!failed_) {
      Space();
      if (i_ >= s_.size() || s_[i_] != '"') return Problem("expected a member name"), v;
      std::string key = String();
      Space();
      if (i_ >= s_.size() || s_[i_] != ':') return Problem("expected ':'"), v;
      ++i_;
      v.object.emplace_back(std::move(key), Value(depth + 1));
      Space();
      if (i_ < s_.size() && s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (i_ < s_.size() && s_[i_] == '}') return ++i_, v;
      Problem("expected ',' or '}'");
    }
    return v;
  }

  JsonValue Elements(int depth) {
    JsonValue v = JsonValue::Array();
    ++i_;
    Space();
    if (i_ < s_.size() && s_[i_] == ']') return ++i_, v;
    while (!failed_) {
      v.array.push_back(Value(depth + 1));
      Space();
      if (i_ < s_.size() && s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (i_ < s_.size() && s_[i_] == ']') return ++i_, v;
      Problem("expected ',' or ']'");
    }
    return v;
  }

  JsonValue Number() {
    const char c = s_[i_];
    const char* begin = s_.c_str() + i_;
    char* end = nullptr;
    const double d = std::strtod(begin, &end);
    if (end == begin || !(c == '-' || (c >= '0' && c <= '9'))) {
      Problem("expected a value");
      return JsonValue();
    }
    const std::string text(begin, static_cast<std::size_t>(end - begin));
    i_ += text.size();
    if (text.find_first_of(".eE") == std::string::npos) {  // an integer: keep it exact
      errno = 0;
      char* iend = nullptr;
      if (c == '-') {
        const long long v = std::strtoll(text.c_str(), &iend, 10);
        if (errno == 0 && *iend == '\0') return JsonValue(v);
      } else {
        const unsigned long long v = std::strtoull(text.c_str(), &iend, 10);
        if (errno == 0 && *iend == '\0') return JsonValue(v);
      }
    }
    return JsonValue(d);
  }

  unsigned Hex4() {
    if (i_ + 4 > s_.size()) return Problem("bad \\u escape"), 0u;
    unsigned u = 0;
    for (int k = 0; k < 4; ++k) {
      const char h = s_[i_++];
      u <<= 4;
      if (h >= '0' && h <= '9') {
        u |= static_cast<unsigned>(h - '0');
      } else if (h >= 'a' && h <= 'f') {
        u |= static_cast<unsigned>(h - 'a' + 10);
      } else if (h >= 'A' && h <= 'F') {
        u |= static_cast<unsigned>(h - 'A' + 10);
      } else {
        return Problem("bad \\u escape"), 0u;
      }
    }
    return u;
  }

  static void Utf8(unsigned cp, std::string* out) {
    if (cp < 0x80) {
      *out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      *out += static_cast<char>(0xC0 | (cp >> 6));
      *out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      *out += static_cast<char>(0xE0 | (cp >> 12));
      *out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      *out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      *out += static_cast<char>(0xF0 | (cp >> 18));
      *out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      *out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      *out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  std::string String() {
    ++i_;  // opening quote
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      const char c = s_[i_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= s_.size()) break;
      const char e = s_[i_++];
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u': {
          unsigned cp = Hex4();
          if (cp >= 0xD800 && cp < 0xDC00 && Take("\\u")) {
            const unsigned low = Hex4();
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          }
          Utf8(cp, &out);
          break;
        }
        default:
          Problem("bad escape in a string");
          return out;
      }
    }
    if (i_ >= s_.size()) return Problem("unterminated string"), out;
    ++i_;  // closing quote
    return out;
  }

  const std::string& s_;
  const std::string& source_;
  std::size_t i_ = 0;
  bool failed_ = false;
  std::string message_;
};

}  // namespace

JsonValue::JsonValue(bool b) : type(Type::kBool), boolean(b) {}
JsonValue::JsonValue(int v) : JsonValue(static_cast<long long>(v)) {}
JsonValue::JsonValue(long v) : JsonValue(static_cast<long long>(v)) {}
JsonValue::JsonValue(long long v)
    : type(Type::kNumber), number(static_cast<double>(v)), is_int(true), integer(v) {}
JsonValue::JsonValue(unsigned v) : JsonValue(static_cast<unsigned long long>(v)) {}
JsonValue::JsonValue(unsigned long v) : JsonValue(static_cast<unsigned long long>(v)) {}
JsonValue::JsonValue(unsigned long long v)
    : type(Type::kNumber),
      number(static_cast<double>(v)),
      is_int(true),
      is_unsigned(v > static_cast<unsigned long long>(INT64_MAX)),
      integer(static_cast<int64_t>(v)),
      uinteger(v) {}
JsonValue::JsonValue(double v) : type(Type::kNumber), number(v) {}
JsonValue::JsonValue(std::string s) : type(Type::kString), string(std::move(s)) {}
JsonValue::JsonValue(const char* s) : JsonValue(std::string(s)) {}

JsonValue JsonValue::Object() {
  JsonValue v;
  v.type = Type::kObject;
  return v;
}

JsonValue JsonValue::Array() {
  JsonValue v;
  v.type = Type::kArray;
  return v;
}

JsonValue JsonValue::Numbers(const std::vector<double>& values) {
  JsonValue a = Array();
  for (double v : values) a.Push(v);
  return a;
}

JsonValue& JsonValue::Set(const std::string& key, JsonValue v) {
  (*this)[key] = std::move(v);
  return *this;
}

JsonValue& JsonValue::Push(JsonValue v) {
  if (type == Type::kNull) type = Type::kArray;
  array.push_back(std::move(v));
  return *this;
}

JsonValue& JsonValue::operator[](const std::string& key) {
  if (type == Type::kNull) type = Type::kObject;
  for (auto& [k, v] : object) {
    if (k == key) return v;
  }
  object.emplace_back(key, JsonValue());
  return object.back().second;
}

const JsonValue* JsonValue::get(const std::string& key) const {
  for (const auto& [k, v] : object) {
    if (k == key) return &v;
  }
  return nullptr;
}

Expected<JsonValue> ParseJson(const std::string& text, const std::string& source) {
  return Parser(text, source).Document();
}

void WriteJson(const JsonValue& v, std::ostream& out, bool compact) {
  JsonWriter w(out, compact);
  w.value(v);
}

}  // namespace volcomp::tools
