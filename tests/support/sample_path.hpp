// The path of a file under samples/ of the source tree (tests get VOLCOMP_SOURCE_DIR).
#pragma once

#include <cstdlib>
#include <string>

namespace volcomp::testing {

/// `relative` under samples/, e.g. SamplePath("model/s500.conf").
inline std::string SamplePath(const std::string& relative) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  return std::string(root ? root : ".") + "/samples/" + relative;
}

}  // namespace volcomp::testing
