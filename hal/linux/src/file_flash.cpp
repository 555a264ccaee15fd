// File-backed NOR flash.
#include "volcomp/hal/linux/file_flash.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace volcomp::hal::linux_board {
namespace {

std::string Why(const std::string& path, const char* what) {
  return "flash file " + path + ": " + what + ": " + std::strerror(errno);
}

bool WriteAll(int fd, const uint8_t* p, size_t n, off_t at) {
  while (n > 0) {
    const ssize_t w = ::pwrite(fd, p, n, at);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<size_t>(w);
    at += w;
  }
  return true;
}

std::string DirOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Creates `path` at `size` bytes of 0xFF: temporary file, fsync, rename, fsync of the directory.
std::string CreateErased(const std::string& path, uint32_t size) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return Why(tmp, "cannot create");
  const std::vector<uint8_t> erased(size, 0xFF);
  const bool ok = WriteAll(fd, erased.data(), erased.size(), 0) && ::fsync(fd) == 0;
  const std::string why = ok ? "" : Why(tmp, "cannot write");
  ::close(fd);
  if (!ok) {
    ::unlink(tmp.c_str());
    return why;
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) return Why(path, "cannot rename into place");
  const int dir = ::open(DirOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  return "";
}

}  // namespace

std::string FileFlash::Open(const std::string& path, const Options& options) {
  Close();
  if (options.size == 0 || options.sector_size == 0 || options.program_unit == 0 ||
      options.size % options.sector_size != 0 || options.sector_size % options.program_unit != 0) {
    return "flash file " + path + ": size must be a multiple of the sector size, and the sector "
           "size a multiple of the program unit";
  }
  options_ = options;
  path_ = path;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) return Why(path, "cannot stat");
    const std::string why = CreateErased(path, options.size);
    if (!why.empty()) return why;
  } else if (!S_ISREG(st.st_mode)) {
    return "flash file " + path + ": not a regular file";
  } else if (static_cast<uint64_t>(st.st_size) != options.size) {
    return "flash file " + path + ": size is " + std::to_string(st.st_size) + " bytes, expected " +
           std::to_string(options.size) + " (another layout; move it away to start empty)";
  }
  fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0) return Why(path, "cannot open");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const std::string why = errno == EWOULDBLOCK
                                ? "flash file " + path + ": in use by another process"
                                : Why(path, "cannot lock");
    Close();
    return why;
  }
  storage_.assign((options.size + 7) / 8, ~uint64_t{0});
  size_t done = 0;
  while (done < options.size) {
    const ssize_t r = ::pread(fd_, bytes() + done, options.size - done, static_cast<off_t>(done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      const std::string why = Why(path, "cannot read");
      Close();
      return why;
    }
    done += static_cast<size_t>(r);
  }
  counters_ = Counters();
  last_error_.clear();
  return "";
}

void FileFlash::Close() {
  if (fd_ >= 0) ::close(fd_);  // also releases the lock
  fd_ = -1;
}

Status FileFlash::WriteThrough(uint32_t offset, uint32_t size) {
  if (!WriteAll(fd_, bytes() + offset, size, static_cast<off_t>(offset)) ||
      (options_.sync && ::fdatasync(fd_) != 0)) {
    last_error_ = Why(path_, "write failed");
    return Error::kIoError;
  }
  return Status::Ok();
}

Status FileFlash::DoErase(uint32_t offset) {
  if (fd_ < 0) return Error::kNotReady;
  std::memset(bytes() + offset, 0xFF, options_.sector_size);
  ++counters_.erases;
  return WriteThrough(offset, options_.sector_size);
}

Status FileFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t size) {
  if (fd_ < 0) return Error::kNotReady;
  uint8_t* dst = bytes() + offset;
  for (uint32_t i = 0; i < size; ++i) {
    if ((dst[i] & data[i]) != data[i]) {  // NOR: programming cannot set a bit
      ++counters_.refused;
      return Error::kIoError;
    }
  }
  std::memcpy(dst, data, size);
  ++counters_.programs;
  const Status s = WriteThrough(offset, size);
  if (!s.ok()) ++counters_.refused;
  return s;
}

}  // namespace volcomp::hal::linux_board
