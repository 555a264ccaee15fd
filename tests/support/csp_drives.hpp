// The CSP drive set the gateway tests and benchmarks use: drive n (1..axes) <-> axis n-1, RPDO1
// 0x200+n = controlword + target position at offset 2, TPDO1 0x180+n = statusword + actual
// position at offset 2 (the usual CiA 402 default PDO mapping of a CSP drive).
#pragma once

#include <cstdint>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/gateway/csp_gateway.hpp"

namespace volcomp::testing {

inline gateway::GatewayConfig CspDriveMapping(uint8_t axes, uint8_t own_node_id = 0) {
  gateway::GatewayConfig c;
  c.own_node_id = own_node_id;
  for (uint8_t a = 0; a < axes; ++a) {
    c.map[c.map_count++] = {static_cast<uint16_t>(0x201 + a), gateway::PdoField::kTargetPosition, 2,
                            a};
    c.map[c.map_count++] = {static_cast<uint16_t>(0x181 + a), gateway::PdoField::kActualPosition, 2,
                            a};
  }
  return c;
}

/// A 6-byte PDO of that layout: `word` then the position, both little-endian (written byte by
/// byte, independently of lib/'s byte_order.hpp, which the gateway uses).
inline CanFrame CspPdo(uint32_t id, int32_t pos, uint16_t word = 0x000F) {
  CanFrame f;
  f.id = id;
  f.dlc = 6;
  f.data[0] = static_cast<uint8_t>(word);
  f.data[1] = static_cast<uint8_t>(word >> 8);
  const uint32_t u = static_cast<uint32_t>(pos);
  for (int i = 0; i < 4; ++i) f.data[2 + i] = static_cast<uint8_t>(u >> (8 * i));
  return f;
}

/// The position of such a PDO.
inline int32_t CspPdoPosition(const CanFrame& f) {
  uint32_t u = 0;
  for (int i = 0; i < 4; ++i) u |= uint32_t{f.data[2 + i]} << (8 * i);
  return static_cast<int32_t>(u);
}

}  // namespace volcomp::testing
