// A simulated flash whose every erase and program is written through to a file at once, as the
// real board's flash keeps every completed operation: killing the simulator (SIGKILL, a crash) is
// then a real power loss, and the next start reads the flash exactly as the operations left it.
//
// It wraps the MockFlash that holds the content (fault injection stays there) and, after each
// operation, writes the bytes it touched (the whole sector for an erase, the programmed range for
// a program; also a failed, interrupted operation's partial result) to the same offsets of the
// file with pwrite(). The page cache keeps them across the process's death; no fsync (a host
// crash is not what this models). The file is opened by Open(); an operation whose bytes cannot
// be written to it fails with kIoError, as a flash that lost the operation would.
// Thread-safety: one thread, like the board.
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

class WriteThroughFlash final : public hal::Flash {
 public:
  /// `flash` must outlive this object; the file is `path`, opened by Open().
  WriteThroughFlash(hal::mock::MockFlash* flash, std::string path);
  /// Opens the file (created if missing); kIoError "PATH: cannot open: REASON".
  Outcome Open();
  /// Sets the file to the flash's whole content (after it was loaded or set at start-up);
  /// kIoError "PATH: write failed: REASON".
  Outcome WriteAll() { return WriteBack(0, flash_->size()); }
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
  Outcome WriteBack(uint32_t offset, uint32_t bytes);

  hal::mock::MockFlash* flash_;
  std::string path_;
  int fd_ = -1;
};

}  // namespace volcomp::sim
