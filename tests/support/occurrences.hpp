// Counting what a rendered text holds (SVG elements, lines of a kind) in tests.
#pragma once

#include <cstddef>
#include <string>

namespace volcomp::testing {

/// How often `what` (not empty) occurs in `text`, overlaps included.
inline std::size_t Occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

}  // namespace volcomp::testing
