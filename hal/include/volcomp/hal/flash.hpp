// Non-volatile storage for table banks and configuration, with NOR-flash semantics:
// Erase() sets a whole sector to 0xFF; Program() may only clear bits (1 -> 0) and writes in units
// of program_unit() bytes at aligned offsets; Map() gives a read-only pointer for reading in place
// (the MCU reads tables directly from flash; the lookup never copies them).
// All offsets are relative to the start of the region this object represents.
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/base/status.hpp"

namespace volcomp::hal {

class Flash {
 public:
  uint32_t size() const { return DoSize(); }
  uint32_t sector_size() const { return DoSectorSize(); }
  uint32_t program_unit() const { return DoProgramUnit(); }

  /// Erases the sector containing `offset` (must be sector aligned). kOutOfRange / kIoError.
  Status Erase(uint32_t offset) {
    if (offset % sector_size() != 0 || offset >= size()) return Error::kOutOfRange;
    return DoErase(offset);
  }
  /// Programs `size` bytes (multiple of program_unit(), aligned). kOutOfRange / kIoError.
  Status Program(uint32_t offset, const uint8_t* data, uint32_t bytes) {
    if (offset % program_unit() != 0 || bytes % program_unit() != 0 || offset > size() ||
        bytes > size() - offset) {
      return Error::kOutOfRange;
    }
    return DoProgram(offset, data, bytes);
  }
  /// Pointer to `offset` for reading in place; valid until the next Erase/Program there.
  const uint8_t* Map(uint32_t offset) const { return DoMap(offset); }

 protected:
  ~Flash() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual uint32_t DoSize() const = 0;
  virtual uint32_t DoSectorSize() const = 0;
  virtual uint32_t DoProgramUnit() const = 0;
  virtual Status DoErase(uint32_t offset) = 0;
  virtual Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) = 0;
  virtual const uint8_t* DoMap(uint32_t offset) const = 0;
};

}  // namespace volcomp::hal
