// Fake GPIO: in-memory lines plus an optional state file.
#include "volcomp/hal/linux/fake_gpio.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace volcomp::hal::linux_board {

Expected<void> FakeGpio::Open(const GpioConfig& /*config*/) {
  mtime_ns_ = file_size_ = -1;
  for (int i = 0; i < kInputLineCount; ++i) file_has_[i] = false;
  if (path_.empty()) return Expected<void>::Ok();
  const Expected<void> loaded = LoadFile();
  if (!loaded.ok()) return loaded;
  return SaveOutputs();
}

Expected<void> FakeGpio::LoadFile() {
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) {
    if (errno != ENOENT) {
      return Fail(Error::kIoError, "fake gpio " + path_ + ": " + std::strerror(errno));
    }
    for (int i = 0; i < kInputLineCount; ++i) file_has_[i] = false;
    mtime_ns_ = file_size_ = -1;
    return Expected<void>::Ok();
  }
  const int64_t mtime = static_cast<int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
  if (mtime == mtime_ns_ && st.st_size == file_size_) return Expected<void>::Ok();
  mtime_ns_ = mtime;
  file_size_ = st.st_size;
  ++file_reads_;
  std::ifstream in(path_);
  bool has[kInputLineCount] = {};
  bool level[kInputLineCount] = {};
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::string name, value;
    const size_t eq = line.find('=');
    std::istringstream(line.substr(0, eq)) >> name;
    if (name.empty()) continue;
    if (eq != std::string::npos) std::istringstream(line.substr(eq + 1)) >> value;
    InputLine which;
    if (!InputLineFromName(name, &which) || (value != "0" && value != "1")) {
      return Fail(Error::kInvalidArgument, "fake gpio " + path_ + ":" + std::to_string(number) +
                                               ": expected <input>=0|1, got '" + line + "'");
    }
    has[static_cast<int>(which)] = true;
    level[static_cast<int>(which)] = value == "1";
  }
  for (int i = 0; i < kInputLineCount; ++i) {
    file_has_[i] = has[i];
    from_file_[i] = level[i];
  }
  return Expected<void>::Ok();
}

Expected<void> FakeGpio::ReadInputs(bool* levels) {
  Expected<void> loaded = path_.empty() ? Expected<void>::Ok() : LoadFile();
  for (int i = 0; i < kInputLineCount; ++i) levels[i] = file_has_[i] ? from_file_[i] : memory_[i];
  return loaded;
}

Expected<void> FakeGpio::WriteOutput(OutputLine line, bool active) {
  const int i = static_cast<int>(line);
  if (i < 0 || i >= kOutputLineCount || out_[i] == active) return Expected<void>::Ok();
  out_[i] = active;
  return path_.empty() ? Expected<void>::Ok() : SaveOutputs();
}

Expected<void> FakeGpio::SaveOutputs() const {
  const std::string out = path_ + ".out";
  const std::string tmp = out + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    for (int i = 0; i < kOutputLineCount; ++i) {
      f << OutputLineName(static_cast<OutputLine>(i)) << "=" << (out_[i] ? 1 : 0) << "\n";
    }
    if (!f) return Fail(Error::kIoError, "fake gpio " + tmp + ": cannot write");
  }
  if (std::rename(tmp.c_str(), out.c_str()) != 0) {
    return Fail(Error::kIoError, "fake gpio " + out + ": " + std::strerror(errno));
  }
  return Expected<void>::Ok();
}

std::string FakeGpio::Describe() const {
  return path_.empty() ? "fake (in memory)" : "fake (state file " + path_ + ")";
}

}  // namespace volcomp::hal::linux_board
