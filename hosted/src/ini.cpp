// INI text: the reader, the value checks and the writer.
#include "volcomp/hosted/ini.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace volcomp::hosted {

std::string Trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A comment starts at '#' or ';' at the start of the line or after white space.
std::string StripComment(const std::string& s) {
  for (size_t i = 0; i < s.size(); ++i) {
    if ((s[i] == '#' || s[i] == ';') &&
        (i == 0 || std::isspace(static_cast<unsigned char>(s[i - 1])))) {
      return s.substr(0, i);
    }
  }
  return s;
}

// Numbers are read into int64_t; anything beyond this is "out of range" before any limit.
constexpr int64_t kReadLimit = int64_t{1} << 40;
// A decimal x 1e9 (up to 1e8 with 9 decimals: a steps-per-mm count); x 10 still fits int64.
constexpr int64_t kDecimalReadLimit = 100000000000000000;

}  // namespace

std::string IniError::ToString() const {
  return line > 0 ? source + ":" + std::to_string(line) + ": " + message : source + ": " + message;
}

std::string IniSection::Title() const { return "[" + name + (arg.empty() ? "" : " " + arg) + "]"; }

const IniEntry* IniSection::Find(const std::string& key) const {
  const std::string lower = Lower(key);
  for (const IniEntry& e : entries) {
    if (e.key == lower) return &e;
  }
  return nullptr;
}

Unexpected<IniError> IniDocument::FailAt(int line, const std::string& message) const {
  return Fail(IniError{source_, line, message});
}

IniExpected<IniDocument> IniDocument::Parse(const std::string& text, const std::string& source) {
  IniDocument doc;
  doc.source_ = source;
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const std::string line = Trim(StripComment(raw));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') return doc.FailAt(number, "expected [section]");
      std::istringstream head(line.substr(1, line.size() - 2));
      IniSection s;
      s.line = number;
      std::string extra;
      head >> s.name >> s.arg;
      if (s.name.empty() || (head >> extra)) {
        return doc.FailAt(number, "bad section header " + line);
      }
      s.name = Lower(s.name);
      if (const IniSection* first = doc.Find(s.name, s.arg); first != nullptr) {
        return doc.FailAt(number, "section " + s.Title() + " appears twice (first at line " +
                                      std::to_string(first->line) + ")");
      }
      doc.sections_.push_back(s);
      continue;
    }
    const size_t eq = line.find('=');
    if (eq == std::string::npos) {
      return doc.FailAt(number, "expected key = value, got '" + line + "'");
    }
    if (doc.sections_.empty()) return doc.FailAt(number, "key outside a [section]");
    IniEntry e{Lower(Trim(line.substr(0, eq))), Trim(line.substr(eq + 1)), number};
    if (const IniEntry* first = doc.sections_.back().Find(e.key); first != nullptr) {
      return doc.FailAt(
          number, e.key + ": given twice (first at line " + std::to_string(first->line) + ")");
    }
    doc.sections_.back().entries.push_back(e);
  }
  return doc;
}

IniExpected<IniDocument> IniDocument::ReadFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Fail(IniError{path, 0, "cannot read the configuration file", Error::kIoError});
  std::ostringstream text;
  text << in.rdbuf();
  return Parse(text.str(), path);
}

const IniSection* IniDocument::Find(const std::string& name, const std::string& arg) const {
  const std::string want = Lower(arg);
  for (const IniSection& s : sections_) {
    if (s.name == name && Lower(s.arg) == want) return &s;
  }
  return nullptr;
}

IniOutcome IniDocument::CheckSections(const std::vector<std::string>& known) const {
  std::string expected;
  for (size_t i = 0; i < known.size(); ++i) {
    expected += (i == 0 ? "" : i + 1 == known.size() ? " or " : ", ") + ("[" + known[i] + "]");
  }
  for (const IniSection& s : sections_) {
    bool ok = false;
    for (const std::string& k : known) {
      const size_t space = k.find(' ');
      const bool takes_arg = space != std::string::npos;
      ok = ok || (s.name == k.substr(0, space) && takes_arg != s.arg.empty());
    }
    if (!ok) return FailAt(s.line, "unknown section " + s.Title() + " (expected " + expected + ")");
  }
  return IniOutcome::Ok();
}

IniOutcome ReadKeys(const IniDocument& doc,
                    const IniSection* section,
                    const std::vector<IniKey>& keys) {
  if (section == nullptr) return IniOutcome::Ok();
  for (const IniEntry& e : section->entries) {
    const IniKey* key = nullptr;
    for (const IniKey& k : keys) {
      if (Lower(k.key) == e.key) key = &k;  // "low_C" is written as it reads; any case matches
    }
    if (key == nullptr) {
      std::string known;
      for (const IniKey& k : keys) known += (known.empty() ? "" : ", ") + k.key;
      return doc.FailAt(
          e.line, "unknown key '" + e.key + "' in " + section->Title() + " (known: " + known + ")");
    }
    VOLCOMP_TRY(key->read(e));
  }
  return IniOutcome::Ok();
}

std::string RangeViolation(int64_t v, int64_t low, int64_t high) {
  if (v < low) return "below the lowest value " + std::to_string(low);
  if (v > high) return "above the highest value " + std::to_string(high);
  return "";
}

IniExpected<int64_t> ReadInteger(
    const IniDocument& doc, const IniEntry& e, int64_t low, int64_t high, const std::string& of) {
  const std::string& v = e.value;
  size_t i = 0;
  const bool negative = !v.empty() && v[0] == '-';
  if (negative) i = 1;
  int base = 10;
  if (v.size() > i + 2 && v[i] == '0' && (v[i + 1] == 'x' || v[i + 1] == 'X')) {
    base = 16;
    i += 2;
  }
  if (i == v.size()) return doc.FailKey(e, "expected a number, got '" + v + "'");
  int64_t x = 0;
  for (; i < v.size(); ++i) {
    const int c = std::tolower(static_cast<unsigned char>(v[i]));
    int d = -1;
    if (c >= '0' && c <= '9') d = c - '0';
    if (base == 16 && c >= 'a' && c <= 'f') d = c - 'a' + 10;
    if (d < 0) return doc.FailKey(e, "expected a number, got '" + v + "'");
    x = x * base + d;
    if (x > kReadLimit) return doc.FailKey(e, v + " is out of range");
  }
  if (negative) x = -x;
  if (const std::string why = RangeViolation(x, low, high); !why.empty()) {
    return doc.FailAt(e.line, e.key + " = " + v + ": " + why + of);
  }
  return x;
}

IniExpected<int64_t> ReadDecimal(const IniDocument& doc,
                                 const IniEntry& e,
                                 int decimals,
                                 int64_t low,
                                 int64_t high,
                                 const std::string& of) {
  const std::string& v = e.value;
  const bool negative = !v.empty() && v[0] == '-';
  const std::string digits = negative ? v.substr(1) : v;
  const size_t dot = digits.find('.');
  const std::string whole = digits.substr(0, dot);
  const std::string frac = dot == std::string::npos ? "" : digits.substr(dot + 1);
  const size_t places = static_cast<size_t>(decimals);
  if ((whole.empty() && frac.empty()) || frac.size() > places) {
    return doc.FailKey(e, "expected a decimal with at most " + std::to_string(decimals) +
                              " decimals, got '" + v + "'");
  }
  int64_t x = 0;
  for (char c : whole + frac + std::string(places - frac.size(), '0')) {
    if (c < '0' || c > '9') return doc.FailKey(e, "expected a decimal, got '" + v + "'");
    x = x * 10 + (c - '0');
    if (x > kDecimalReadLimit) return doc.FailKey(e, v + " is out of range");
  }
  if (negative) x = -x;
  if (const std::string why = RangeViolation(x, low, high); !why.empty()) {
    return doc.FailAt(
        e.line, e.key + " = " + v + ": " + why + " (x 1e-" + std::to_string(decimals) + ")" + of);
  }
  return x;
}

IniExpected<int64_t> ReadDecimalE9(
    const IniDocument& doc, const IniEntry& e, int64_t low, int64_t high, const std::string& of) {
  return ReadDecimal(doc, e, 9, low, high, of);
}

IniExpected<bool> ReadBool(const IniDocument& doc, const IniEntry& e) {
  const std::string v = Lower(e.value);
  if (v == "true" || v == "yes" || v == "on" || v == "1") return true;
  if (v == "false" || v == "no" || v == "off" || v == "0") return false;
  return doc.FailKey(e, "expected true or false, got '" + e.value + "'");
}

IniExpected<size_t> ReadChoice(const IniDocument& doc,
                               const IniEntry& e,
                               const std::vector<std::string>& names) {
  const std::string v = Lower(e.value);
  std::string known;
  for (size_t i = 0; i < names.size(); ++i) {
    if (v == names[i]) return i;
    known += (i == 0 ? "" : " | ") + names[i];
  }
  return doc.FailKey(e, "expected " + known + ", got '" + e.value + "'");
}

void IniWriter::Comment(const std::string& text) { text_ += "# " + text + "\n"; }

void IniWriter::Section(const std::string& title) {
  text_ += (text_.empty() ? "[" : "\n[") + title + "]\n";
}

void IniWriter::Key(const std::string& key, const std::string& value, const std::string& comment) {
  std::string line = key + " = " + value;
  if (!comment.empty()) {
    if (line.size() < 32) line.resize(32, ' ');
    line += " # " + comment;
  }
  text_ += line + "\n";
}

std::string FormatDecimalE9(int64_t v) {
  char text[40];
  std::snprintf(text, sizeof text, "%s%lld.%09lld", v < 0 ? "-" : "",
                static_cast<long long>((v < 0 ? -v : v) / 1000000000),
                static_cast<long long>((v < 0 ? -v : v) % 1000000000));
  std::string u = text;
  while (u.back() == '0') u.pop_back();
  if (u.back() == '.') u.pop_back();
  return u;
}

std::string FormatHex(uint32_t value, int digits) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%0*X", digits, value);
  return text;
}

}  // namespace volcomp::hosted
