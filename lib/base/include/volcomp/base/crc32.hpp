// CRC-32 (IEEE 802.3 / zlib: polynomial 0x04C11DB7 reflected, init and final XOR 0xFFFFFFFF).
//
// Incremental: Crc32 c; c.Update(a, n); c.Update(b, m); c.value(). Check value: "123456789" gives
// 0xCBF43926. Table-driven (1 KiB table in flash), safe to call from any context.
#pragma once

#include <cstddef>
#include <cstdint>

namespace volcomp {

class Crc32 {
 public:
  void Update(const uint8_t* data, size_t size);
  uint32_t value() const { return ~state_; }

 private:
  uint32_t state_ = 0xFFFFFFFFu;
};

/// CRC-32 of a whole buffer.
uint32_t ComputeCrc32(const uint8_t* data, size_t size);

}  // namespace volcomp
