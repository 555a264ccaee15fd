// Flash operations written through to a file.
#include "volcomp/sim/write_through_flash.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace volcomp::sim {

WriteThroughFlash::WriteThroughFlash(hal::mock::MockFlash* flash, const std::string& path)
    : flash_(flash), path_(path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
}

WriteThroughFlash::~WriteThroughFlash() {
  if (fd_ >= 0) ::close(fd_);
}

void WriteThroughFlash::WriteBack(uint32_t offset, uint32_t bytes) {
  const uint8_t* p = flash_->raw().data() + offset;
  while (bytes > 0) {
    const ssize_t n = ::pwrite(fd_, p, bytes, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(path_ + ": write failed: " + std::strerror(errno));
    p += n;
    offset += static_cast<uint32_t>(n);
    bytes -= static_cast<uint32_t>(n);
  }
}

Status WriteThroughFlash::DoErase(uint32_t offset) {
  const Status s = flash_->Erase(offset);
  WriteBack(offset, flash_->sector_size());
  return s;
}

Status WriteThroughFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) {
  const Status s = flash_->Program(offset, data, bytes);
  WriteBack(offset, bytes);
  return s;
}

}  // namespace volcomp::sim
