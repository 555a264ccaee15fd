// CRC-16/XMODEM, table-driven (the table is built at compile time).
#include "volcomp/canopen/crc16.hpp"

namespace volcomp::canopen {
namespace {

struct Table {
  uint16_t entry[256];
  constexpr Table() : entry() {
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i << 8;
      for (int k = 0; k < 8; ++k) c = (c & 0x8000u) ? ((c << 1) ^ 0x1021u) : (c << 1);
      entry[i] = static_cast<uint16_t>(c);
    }
  }
};
constexpr Table kTable;

}  // namespace

uint16_t Crc16Update(uint16_t crc, const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) {
    crc = static_cast<uint16_t>((crc << 8) ^ kTable.entry[((crc >> 8) ^ data[i]) & 0xFFu]);
  }
  return crc;
}

}  // namespace volcomp::canopen
