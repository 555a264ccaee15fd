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

}  // namespace volcomp::report
