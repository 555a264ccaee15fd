// Text helpers shared by the Etalon exchange and ISG-CSV readers and writers.
#pragma once

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "trim.hpp"

namespace volcomp::datasets::iso230_text {

/// The line without a `//` comment, CR and surrounding blanks.
inline std::string Content(const std::string& line) {
  const std::size_t c = line.find("//");
  return Trim(c == std::string::npos ? line : line.substr(0, c));
}

/// Whitespace-separated words.
inline std::vector<std::string> Words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

inline std::string Upper(std::string s) {
  for (char& c : s) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return s;
}

/// `v` with `decimals` decimals (the writers' precision).
inline std::string Fixed(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

inline constexpr int kArgumentDecimals = 6;
inline constexpr int kValueDecimals = 12;

/// `header` as `//` comment lines.
inline std::string CommentLines(const std::vector<std::string>& header) {
  std::string out;
  for (const std::string& h : header) out += h.empty() ? "//\n" : "// " + h + "\n";
  return out;
}

}  // namespace volcomp::datasets::iso230_text
