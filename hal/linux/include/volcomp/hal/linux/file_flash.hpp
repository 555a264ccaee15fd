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
// default), fdatasync()ed before it returns. Operations therefore reach the disk in program order,
// which is what the dual-bank store relies on (data before commit record); a power loss during
// one operation tears at most that operation, which the store treats like an interrupted flash
// program. A new file is created at the full size filled with 0xFF (written to a temporary file,
// fsynced and renamed into place, then the directory is fsynced), so a crash while creating never
// leaves a short file. A file of another size is refused (the layout would not match). The file
// is locked (flock, exclusive) while open, so two processes cannot share one flash.
//
// Thread-safety: one thread (the firmware's main loop), like every hal::Flash.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hal/flash.hpp"

namespace volcomp::hal::linux_board {

class FileFlash final : public Flash {
 public:
  struct Options {
    uint32_t size = 1u << 20;
    uint32_t sector_size = 4096;
    uint32_t program_unit = 8;
    bool sync = true;  // fdatasync after every operation
  };
  struct Counters {
    uint64_t erases = 0;
    uint64_t programs = 0;
    uint64_t refused = 0;  // programs refused for a 0 -> 1 change or an I/O error
  };

  FileFlash() = default;
  ~FileFlash() { Close(); }
  FileFlash(const FileFlash&) = delete;
  FileFlash& operator=(const FileFlash&) = delete;

  /// Opens (or creates) `path`. Returns "" or a message naming the file and the cause.
  std::string Open(const std::string& path, const Options& options);
  void Close();
  bool is_open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  const Counters& counters() const { return counters_; }
  /// The last I/O error text ("" when none).
  const std::string& last_error() const { return last_error_; }

 private:
  uint32_t DoSize() const override { return options_.size; }
  uint32_t DoSectorSize() const override { return options_.sector_size; }
  uint32_t DoProgramUnit() const override { return options_.program_unit; }
  Status DoErase(uint32_t offset) override;
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override;
  const uint8_t* DoMap(uint32_t offset) const override { return bytes() + offset; }

  uint8_t* bytes() { return reinterpret_cast<uint8_t*>(storage_.data()); }
  const uint8_t* bytes() const { return reinterpret_cast<const uint8_t*>(storage_.data()); }
  Status WriteThrough(uint32_t offset, uint32_t size);

  Options options_;
  std::string path_;
  int fd_ = -1;
  std::vector<uint64_t> storage_;  // 8-byte aligned image of the file
  Counters counters_;
  std::string last_error_;
};

}  // namespace volcomp::hal::linux_board
