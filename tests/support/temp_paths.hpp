// Paths of the files and folders tests write, in the test framework's temporary folder. Test cases
// run in parallel (one process each): every test names its own files, or takes a ScratchDir.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace volcomp::testing {

/// `name` in the temporary folder, prefixed "volcomp_" (e.g. TempPath("build_grid_ok.vct")).
inline std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "volcomp_" + name;
}

/// TempPath(name) with nothing there: what was left by an earlier run is removed.
inline std::string FreshTempPath(const std::string& name) {
  const std::string path = TempPath(name);
  std::filesystem::remove_all(path);
  return path;
}

/// A new folder of its own in the temporary folder (TempPath(name) plus a unique suffix), removed
/// with everything in it when the object goes, whatever the test's outcome.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name = "scratch") {
    std::string pattern = TempPath(name) + ".XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    if (mkdtemp(buf.data()) != nullptr) {
      path_ = buf.data();
    } else {
      ADD_FAILURE() << "cannot create a folder like " << pattern;
    }
  }
  ~ScratchDir() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::string& path() const { return path_; }
  /// The path of `name` in the folder.
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

}  // namespace volcomp::testing
