// Flash operations written through to a file.
#include "volcomp/sim/write_through_flash.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace volcomp::sim {

WriteThroughFlash::WriteThroughFlash(hal::mock::MockFlash* flash, std::string path)
    : flash_(flash), path_(std::move(path)) {}

Outcome WriteThroughFlash::Open() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) return Fail(Error::kIoError, path_ + ": cannot open: " + std::strerror(errno));
  return Outcome::Ok();
}

WriteThroughFlash::~WriteThroughFlash() {
  if (fd_ >= 0) ::close(fd_);
}

Outcome WriteThroughFlash::WriteBack(uint32_t offset, uint32_t bytes) {
  const uint8_t* p = flash_->raw().data() + offset;
  while (bytes > 0) {
    const ssize_t n = ::pwrite(fd_, p, bytes, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const char* reason = fd_ < 0 ? "not open" : std::strerror(errno);
      return Fail(Error::kIoError, path_ + ": write failed: " + reason);
    }
    p += n;
    offset += static_cast<uint32_t>(n);
    bytes -= static_cast<uint32_t>(n);
  }
  return Outcome::Ok();
}

Status WriteThroughFlash::DoErase(uint32_t offset) {
  const Status s = flash_->Erase(offset);
  if (!WriteBack(offset, flash_->sector_size()).ok()) return Error::kIoError;
  return s;
}

Status WriteThroughFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) {
  const Status s = flash_->Program(offset, data, bytes);
  if (!WriteBack(offset, bytes).ok()) return Error::kIoError;
  return s;
}

}  // namespace volcomp::sim
