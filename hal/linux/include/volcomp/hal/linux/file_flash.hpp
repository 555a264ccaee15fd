// hal::Flash backed by a file (Linux board), with the NOR semantics of the MCU flash and MockFlash
// so DualBankStore works unchanged: Erase() sets a sector to 0xFF, Program() may only clear bits
// (else kIoError, nothing written), Map() points into an in-memory copy valid until the next
// Erase/Program of that range. Operations reach the disk in program order (fdatasync with `sync`),
// optionally written behind on an internal thread; a write error is sticky (kIoError). Threading:
// the hal::Flash interface from one thread. Durability rules: docs/linux-board.md, "Flash files".
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
