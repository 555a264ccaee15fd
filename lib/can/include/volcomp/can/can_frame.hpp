// A classic CAN 2.0A/B frame (8 data bytes max): the unit every CAN layer of volcomp exchanges.
#pragma once

#include <cstdint>

namespace volcomp {

struct CanFrame {
  uint32_t id = 0;  // 11-bit, or 29-bit when extended
  bool extended = false;
  bool rtr = false;
  uint8_t dlc = 0;  // 0..8
  uint8_t data[8] = {};

  /// True when id and dlc are in range for the frame format.
  constexpr bool valid() const { return dlc <= 8 && id <= (extended ? 0x1FFFFFFFu : 0x7FFu); }
};

inline bool operator==(const CanFrame& a, const CanFrame& b) {
  if (a.id != b.id || a.extended != b.extended || a.rtr != b.rtr || a.dlc != b.dlc) return false;
  for (uint8_t i = 0; i < a.dlc && !a.rtr; ++i) {
    if (a.data[i] != b.data[i]) return false;
  }
  return true;
}
inline bool operator!=(const CanFrame& a, const CanFrame& b) { return !(a == b); }

/// Bits a frame occupies on the wire: SOF .. EOF plus the 3-bit interframe space, with the stuff
/// bits the bit-stuffing rule inserts for this exact frame (computed over SOF .. CRC, where
/// stuffing applies). Used by the simulated bus to spend real frame time.
uint32_t CanFrameBits(const CanFrame& frame);

}  // namespace volcomp
