// CiA 301 frames written out by hand for the configuration tests: an expedited SDO download
// (request 0x600 + node: command 0x23/0x2B/0x2F for 4/2/1 data bytes, index little-endian,
// sub-index, data) and an NMT command (COB-ID 0: command, node). Independent of the client code.
#pragma once

#include <cstdint>

#include "volcomp/can/can_frame.hpp"

namespace volcomp::testing {

inline CanFrame SdoDownload(
    uint8_t node, uint16_t index, uint8_t sub, uint32_t value, uint8_t bytes) {
  CanFrame f;
  f.id = 0x600u + node;
  f.dlc = 8;
  f.data[0] = bytes == 1 ? 0x2F : bytes == 2 ? 0x2B : 0x23;
  f.data[1] = static_cast<uint8_t>(index);
  f.data[2] = static_cast<uint8_t>(index >> 8);
  f.data[3] = sub;
  for (int i = 0; i < 4; ++i) f.data[4 + i] = static_cast<uint8_t>(value >> (8 * i));
  return f;
}

/// True for the server's "download done" answer to `index`:`sub` (0x580 + node, command 0x60).
inline bool IsDownloadDone(const CanFrame& f, uint8_t node, uint16_t index, uint8_t sub) {
  return f.id == 0x580u + node && f.dlc == 8 && f.data[0] == 0x60 &&
         f.data[1] == static_cast<uint8_t>(index) &&
         f.data[2] == static_cast<uint8_t>(index >> 8) && f.data[3] == sub;
}

inline CanFrame NmtResetNode(uint8_t node) {
  CanFrame f;
  f.id = 0;
  f.dlc = 2;
  f.data[0] = 0x81;  // reset node
  f.data[1] = node;
  return f;
}

constexpr uint32_t kSave = 0x65766173;  // "save" (CiA 301 0x1010)

}  // namespace volcomp::testing
