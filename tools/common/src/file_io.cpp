// Whole-file reading and writing.
#include "volcomp/tools/file_io.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace volcomp::tools {
namespace {

Unexpected<Failure> IoFailure(const std::string& path, const char* what) {
  const int e = errno;
  return Fail(Error::kIoError,
              path + ": " + what + (e != 0 ? std::string(": ") + std::strerror(e) : ""));
}

}  // namespace

Expected<std::vector<uint8_t>> ReadFileBytes(const std::string& path) {
  errno = 0;
  std::ifstream f(path, std::ios::binary);
  if (!f) return IoFailure(path, "cannot open");
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) return IoFailure(path, "cannot read");
  return bytes;
}

Expected<std::string> ReadTextFile(const std::string& path) {
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
    return text.str();
  }
  errno = 0;
  std::ifstream f(path, std::ios::binary);
  if (!f) return IoFailure(path, "cannot open");
  text << f.rdbuf();
  if (f.bad()) return IoFailure(path, "cannot read");
  return text.str();
}

Outcome WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  errno = 0;
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) return IoFailure(path, "cannot open for writing");
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  f.close();
  if (!f) return IoFailure(path, "cannot write");
  return Outcome::Ok();
}

Outcome WriteTextFile(const std::string& path, const std::string& text) {
  return WriteFileBytes(path, std::vector<uint8_t>(text.begin(), text.end()));
}

}  // namespace volcomp::tools
