// Number formatting and XML escaping.
#include "volcomp/report/format.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace volcomp::report {

std::string FormatFixed(double value, int decimals) {
  if (!std::isfinite(value)) return "n/a";
  if (decimals < 0) decimals = 0;
  if (decimals > 12) decimals = 12;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  // A value that rounds to zero prints without a minus sign.
  if (s[0] == '-' && s.find_first_of("123456789") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string FormatSigned(double value, int decimals) {
  std::string s = FormatFixed(value, decimals);
  if (s != "n/a" && s[0] != '-') s.insert(0, "+");
  return s;
}

std::string FormatNumber(double value, int significant) {
  std::ostringstream s;
  s.precision(significant);
  s << value;
  return s.str();
}

std::string EscapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::size_t DisplayWidth(const std::string& s) {
  std::size_t w = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if ((c & 0xC0) == 0x80) continue;
    if (c == 0xCC ||
        (c == 0xCD && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) < 0xB0)) {
      continue;  // combining diacritical mark
    }
    ++w;
  }
  return w;
}

std::string PadRight(const std::string& text, std::size_t width) {
  const std::size_t w = DisplayWidth(text);
  return w >= width ? text : text + std::string(width - w, ' ');
}

}  // namespace volcomp::report
