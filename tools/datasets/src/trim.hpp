// Text without the spaces, tabs (and a CR at the end) around it, for the readers' fields.
#pragma once

#include <string>

namespace volcomp::datasets {

inline std::string Trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

}  // namespace volcomp::datasets
