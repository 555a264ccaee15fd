// A temporary directory for the hal/linux tests, removed with the files handed out.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace volcomp::hal::linux_board::test_support {

class TempDir {
 public:
  TempDir() {
    char t[] = "/tmp/volcomp-hal-test.XXXXXX";
    path_ = mkdtemp(t) != nullptr ? t : "";
  }
  ~TempDir() {
    for (const std::string& f : files_) std::remove((path_ + "/" + f).c_str());
    rmdir(path_.c_str());
  }
  std::string file(const std::string& name) {
    files_.push_back(name);
    files_.push_back(name + ".out");
    files_.push_back(name + ".tmp");
    return path_ + "/" + name;
  }

 private:
  std::string path_;
  std::vector<std::string> files_;
};

inline std::vector<uint8_t> ReadFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(f)), {});
}

}  // namespace volcomp::hal::linux_board::test_support
