// hal::Flash backed by a file (Linux board): the table banks and the stored settings persist in
// ordinary files with the same NOR semantics as the MCU flash and MockFlash, so the firmware's
// power-loss-safe stores (DualBankStore) work unchanged:
//
//   Erase(offset)     the sector becomes 0xFF;
//   Program(...)      may only clear bits (a 0 -> 1 change is refused with kIoError and nothing
//                     is written); offsets and sizes in program units;
//   Map(offset)       a pointer into an in-memory copy (8-byte aligned), valid until the next
//                     Erase/Program of that range.
//
// Durability: every Erase/Program is written with pwrite() at its offset and, with `sync` on (the
// default), fdatasync()ed before the next one is written. Operations therefore reach the disk in
// program order, which is what the dual-bank store relies on (data before commit record); a power
// loss during one operation tears at most that operation, and a power loss with operations still
// queued loses them from the tail, which the store treats like power lost before them (the old
// table stays). A new file is created at the full size filled with 0xFF (temporary file, fsync,
// rename, fsync of the directory), so a crash while creating never leaves a short file. A file of
// another size is refused (the layout would not match). The file is locked (flock, exclusive)
// while open, so two processes cannot share one flash.
//
// Write-behind (`background`, the default): the in-memory copy changes at once and the file writes
// run in order on a writer thread, so the caller (the gateway's event loop, which must keep
// forwarding frames during a table upload) never waits for the disk; fdatasync on an SD card can
// take tens of milliseconds. Flush() and Close() wait until everything queued is on disk. A write
// error is sticky: every later Erase/Program fails with kIoError (write_error() says why). Without
// `background` each operation is written (and synced) before it returns.
//
// Thread-safety: the hal::Flash interface from one thread (the firmware's main loop); the writer
// thread is internal.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "volcomp/hal/flash.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::hal::linux_board {

class FileFlash final : public Flash {
 public:
  struct Options {
    uint32_t size = 1u << 20;
    uint32_t sector_size = 4096;
    uint32_t program_unit = 8;
    bool sync = true;        // fdatasync after every operation
    bool background = true;  // write-behind thread (see above)
  };
  struct Counters {
    uint64_t erases = 0;
    uint64_t programs = 0;
    uint64_t refused = 0;     // programs refused for a 0 -> 1 change or after a write error
    uint64_t max_queued = 0;  // most operations waiting for the writer thread at once
    uint64_t written = 0;     // operations on disk
  };

  FileFlash() = default;
  ~FileFlash() { Close(); }
  FileFlash(const FileFlash&) = delete;
  FileFlash& operator=(const FileFlash&) = delete;

  /// Opens (or creates) `path`. Failures name the file and the cause: kInvalidArgument (geometry),
  /// kBusy (another process holds the file), kConfigInvalid (a file of another size or kind),
  /// kIoError (the system refused).
  Expected<void> Open(const std::string& path, const Options& options);
  /// Waits for queued writes, then closes the file (and releases the lock).
  void Close();
  /// Waits until every operation so far is written (and synced); the write error if one happened.
  Expected<void> Flush();
  bool is_open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  Counters counters() const;
  /// The sticky write error, if any.
  std::optional<Failure> write_error() const;

 private:
  struct Op {
    uint32_t offset;
    std::vector<uint8_t> bytes;
  };

  uint32_t DoSize() const override { return options_.size; }
  uint32_t DoSectorSize() const override { return options_.sector_size; }
  uint32_t DoProgramUnit() const override { return options_.program_unit; }
  Status DoErase(uint32_t offset) override;
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override;
  const uint8_t* DoMap(uint32_t offset) const override { return bytes() + offset; }

  uint8_t* bytes() { return reinterpret_cast<uint8_t*>(storage_.data()); }
  const uint8_t* bytes() const { return reinterpret_cast<const uint8_t*>(storage_.data()); }
  Status Submit(uint32_t offset, uint32_t size);
  Expected<void> WriteOp(const uint8_t* data, uint32_t size, uint32_t offset);
  void WriterLoop();

  Options options_;
  std::string path_;
  int fd_ = -1;
  std::vector<uint64_t> storage_;  // 8-byte aligned image of the file

  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable wake_, idle_;
  std::deque<Op> queue_;
  bool busy_ = false;  // the writer holds an operation
  bool stop_ = false;
  std::optional<Failure> error_;  // sticky write error
  Counters counters_;
  std::thread writer_;
};

}  // namespace volcomp::hal::linux_board
