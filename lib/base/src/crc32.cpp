// CRC-32, byte-wise table lookup; the table is built at compile time.
#include "volcomp/base/crc32.hpp"

namespace volcomp {
namespace {

struct Crc32Table {
  uint32_t entry[256];
  constexpr Crc32Table() : entry() {
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
      entry[i] = c;
    }
  }
};

constexpr Crc32Table kTable;

}  // namespace

void Crc32::Update(const uint8_t* data, size_t size) {
  uint32_t c = state_;
  for (size_t i = 0; i < size; ++i) c = kTable.entry[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  state_ = c;
}

uint32_t ComputeCrc32(const uint8_t* data, size_t size) {
  Crc32 c;
  c.Update(data, size);
  return c.value();
}

}  // namespace volcomp
