// A table image validated and prepared for the native component's servo-thread code, built
// outside that thread: at `loadrt` and by the loader thread on a reload (table_loader.hpp). Once
// built it does not change; the servo thread only reads it (NativeCompensator::UseTable).
//
// Errors are Failures with the whole message a LinuxCNC user needs: the file, the reason (errno
// text; for a file rtapi_app may not read, the uid it runs as and the file's owner and mode), and
// for a bad image the text and name `volcomp inspect` prints ("invalid table image: image CRC-32
// does not match (kImageBadCrc)"). The Failure's code is the value of the `table-error` pin.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "volcomp/control/compensator.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::linuxcnc {

/// One axis of a table: its letter, kind, size of a step and rotary wrap.
struct NativeAxis {
  char name = 0;
  table::AxisKind kind = table::AxisKind::kLinear;
  uint32_t resolution_e9 = 0;      // the image's units per step x 1e9 (pm or ndeg)
  double units_per_step = 0;       // mm (linear) or degrees (rotary) per table step
  uint32_t wrap_period_steps = 0;  // AXIS1D wrap period (rotary), 0 = no wrap
  int32_t wrap_origin_steps = 0;
};

class NativeTable {
 public:
  /// Reads and validates the table file `path`.
  static Expected<std::unique_ptr<NativeTable>> ReadFile(const std::string& path);
  /// Validates `bytes` (kept by the table); `source` names them in messages.
  static Expected<std::unique_ptr<NativeTable>> FromBytes(std::vector<uint8_t> bytes,
                                                          const std::string& source);

  /// An independent copy (the loader keeps one to check reloads against).
  Expected<std::unique_ptr<NativeTable>> Copy(const std::string& source) const {
    return FromBytes(bytes_, source);
  }

  uint8_t axis_count() const { return axis_count_; }
  const NativeAxis& axis(uint8_t a) const { return axes_[a]; }
  /// Index of the axis named `letter` (upper case), or -1.
  int FindAxis(char letter) const;
  /// "X Y Z A": the axis letters.
  std::string AxisNames() const;
  const PreparedTable& prepared() const { return prepared_; }
  uint32_t crc32() const { return prepared_.crc32; }
  size_t size_bytes() const { return bytes_.size(); }

  /// Success when `other` is for the same machine (axis letters, kinds and step sizes), which a
  /// reload requires: the joints are wired to the first table's axes.
  Outcome CheckSameAxes(const NativeTable& other, const std::string& source) const;

 private:
  NativeTable() = default;
  std::vector<uint8_t> bytes_;  // the prepared table points into these
  PreparedTable prepared_;
  uint8_t axis_count_ = 0;
  NativeAxis axes_[table::kMaxAxes];
};

}  // namespace volcomp::linuxcnc
