// CRC-16 of CiA 301 SDO block transfer: CRC-16/XMODEM (polynomial 0x1021, initial value 0, not
// reflected, no final XOR). Check value: "123456789" -> 0x31C3. Incremental.
#pragma once

#include <cstddef>
#include <cstdint>

namespace volcomp::canopen {

uint16_t Crc16Update(uint16_t crc, const uint8_t* data, size_t size);

}  // namespace volcomp::canopen
