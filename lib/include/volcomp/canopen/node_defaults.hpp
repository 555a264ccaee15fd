// What a board without stored settings uses for its CANopen node and bus-side switches: the
// defaults of BoardSettings (firmware/app settings.hpp) and of the dictionary entries bound to them
// (od_entries.def, hence the EDS DefaultValue).
#pragma once

#include <cstdint>

namespace volcomp::canopen {

inline constexpr uint8_t kDefaultNodeId = 0x10;           // 0x2000:1
inline constexpr uint16_t kDefaultBitrateKbit = 1000;     // 0x2000:2
inline constexpr uint16_t kDefaultHeartbeatMs = 1000;     // 0x1017 (0 = off)
inline constexpr uint8_t kDefaultCompensationEnable = 1;  // 0x2121

}  // namespace volcomp::canopen
