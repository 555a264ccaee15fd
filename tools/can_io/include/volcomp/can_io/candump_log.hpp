// candump -L log format: "(SEC.USEC) IFACE FRAME[ DIR]", one frame a line, where FRAME is
// can-utils' compact syntax: 3 hex digits for a standard id, 8 for an extended one, '#', the data
// bytes in uppercase hex, or 'R' (+ the DLC digit when not 0) for a remote frame. DIR is the
// optional " T"/" R" (transmitted/received) that `candump -x` and python-can's writer add.
// Examples: "(1700000000.000123) can0 601#4000100000000000 T", "(1.000000) can0 1ABCDEF0#R2".
//
// Thread-safety: a writer is used from one thread; the parse functions are pure.
#pragma once

#include <chrono>
#include <cstdint>
#include <fstream>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::can_io {

enum class Direction : uint8_t { kNone, kTx, kRx };

struct CandumpRecord {
  uint64_t timestamp_us = 0;  // since the Unix epoch (or any origin the writer used)
  std::string iface;
  CanFrame frame;
  Direction direction = Direction::kNone;
};

/// One log line without newline.
std::string FormatCandumpLine(const CandumpRecord& record);
/// Parses one line (trailing '\r'/'\n' tolerated); a malformed line is a failure
/// (kInputInvalid) saying why.
Expected<CandumpRecord> ParseCandumpLine(const std::string& line);
/// Reads a whole log; blank lines are skipped. The first malformed line is a failure
/// (kInputInvalid, "line N: why").
Expected<std::vector<CandumpRecord>> ReadCandumpLog(std::istream& in);

class CandumpLogWriter {
 public:
  /// Writes to `out` (not owned; must outlive the writer). `iface` is the interface column.
  CandumpLogWriter(std::ostream& out, std::string iface, bool direction_markers = true);
  /// Creates/truncates `path` (kIoError "cannot write CAN log 'PATH'" when it cannot).
  static Expected<std::unique_ptr<CandumpLogWriter>> OpenFile(const std::string& path,
                                                              std::string iface,
                                                              bool direction_markers = true);

  /// Appends one line stamped with the wall-clock time and flushes it (a log survives a crash).
  void Write(const CanFrame& frame, Direction direction);
  /// Appends one line with an explicit timestamp (simulated time, tests).
  void Write(const CanFrame& frame, Direction direction, uint64_t timestamp_us);
  uint64_t lines() const { return lines_; }

 private:
  std::unique_ptr<std::ofstream> file_;  // set when OpenFile created the stream
  std::ostream* out_;
  std::string iface_;
  bool direction_markers_;
  uint64_t lines_ = 0;
};

}  // namespace volcomp::can_io
