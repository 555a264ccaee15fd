// Paths of files in the source tree: ctest gives tests VOLCOMP_SOURCE_DIR; a test binary run by
// hand falls back to VOLCOMP_TEST_SOURCE_DIR where its suite defines it, else the current folder.
#pragma once

#include <cstdlib>
#include <string>

namespace volcomp::testing {

/// `relative` under the source tree, e.g. SourcePath("docs/volcomp.eds").
inline std::string SourcePath(const std::string& relative) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
#ifdef VOLCOMP_TEST_SOURCE_DIR
  if (root == nullptr) root = VOLCOMP_TEST_SOURCE_DIR;
#endif
  return std::string(root ? root : ".") + "/" + relative;
}

/// `relative` under samples/, e.g. SamplePath("model/s500.conf").
inline std::string SamplePath(const std::string& relative) {
  return SourcePath("samples/" + relative);
}

}  // namespace volcomp::testing
