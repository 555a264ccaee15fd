// Written files compared without their comment lines (headers that name sources and paths).
#pragma once

#include <string>

namespace volcomp::testing {

/// `text` without the lines that start with `prefix` ("#", "//"); every kept line ends in '\n'.
inline std::string WithoutCommentLines(const std::string& text, const std::string& prefix) {
  std::string out;
  std::size_t from = 0;
  while (from < text.size()) {
    std::size_t end = text.find('\n', from);
    if (end == std::string::npos) end = text.size();
    if (text.compare(from, prefix.size(), prefix) != 0) out += text.substr(from, end - from) + "\n";
    from = end + 1;
  }
  return out;
}

}  // namespace volcomp::testing
