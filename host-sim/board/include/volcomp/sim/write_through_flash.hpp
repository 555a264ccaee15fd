// A simulated flash whose every erase and program is written through to a file at once, as the
// real board's flash keeps every completed operation: killing the simulator (SIGKILL, a crash) is
// then a real power loss, and the next start reads the flash exactly as the operations left it.
//
// It wraps the MockFlash that holds the content (fault injection stays there) and, after each
// operation, writes the bytes it touched (the whole sector for an erase, the programmed range for
// a program; also a failed, interrupted operation's partial result) to the same offsets of the
// file with pwrite(). The page cache keeps them across the process's death; no fsync (a host
// crash is not what this models). Thread-safety: one thread, like the board.
#pragma once

#include <string>

#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"

namespace volcomp::sim {

class WriteThroughFlash final : public hal::Flash {
 public:
  /// `flash` must outlive this object. Opens the file (created if missing). Throws
  /// std::runtime_error when it cannot be opened (also WriteAll() and the operations when a write
  /// fails).
  WriteThroughFlash(hal::mock::MockFlash* flash, const std::string& path);
  /// Sets the file to the flash's whole content (after it was loaded or set at start-up).
  void WriteAll() { WriteBack(0, flash_->size()); }
  ~WriteThroughFlash();
  WriteThroughFlash(const WriteThroughFlash&) = delete;
  WriteThroughFlash& operator=(const WriteThroughFlash&) = delete;

 private:
  uint32_t DoSize() const override { return flash_->size(); }
  uint32_t DoSectorSize() const override { return flash_->sector_size(); }
  uint32_t DoProgramUnit() const override { return flash_->program_unit(); }
  Status DoErase(uint32_t offset) override;
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override;
  const uint8_t* DoMap(uint32_t offset) const override { return flash_->Map(offset); }
  void WriteBack(uint32_t offset, uint32_t bytes);

  hal::mock::MockFlash* flash_;
  std::string path_;
  int fd_ = -1;
};

}  // namespace volcomp::sim
