// What a board without stored settings uses for its CANopen node and bus-side switches: the
// defaults of BoardSettings (firmware/app settings.hpp) and of the dictionary entries bound to them
// (od_entries.def, hence the EDS DefaultValue).
#pragma once

#include <cstdint>

namespace volcomp::canopen {

inline constexpr uint8_t kDefaultNodeId = 0x10;        // 0x2000:1
inline constexpr uint16_t kDefaultBitrateKbit = 1000;  // 0x2000:2
inline constexpr uint16_t kDefaultHeartbeatMs = 1000;  // 0x1017 (0 = off)
/// 0x1015 EMCY inhibit time, 100 us units: 10 ms. EMCY (COB-ID 0x080 + id) wins arbitration over
/// every PDO and SDO, so a burst of events (a chattering alarm input, a client hammering a locked
/// object: one EMCY pair each) would otherwise delay the controller's setpoints; 10 ms bounds EMCY
/// to 100 frames/s, about 1.4 % of a 1 Mbit/s bus and 11 % of a 125 kbit/s one, while the first
/// EMCY after a quiet spell still leaves at once.
inline constexpr uint16_t kDefaultEmcyInhibit100us = 100;
inline constexpr uint8_t kDefaultCompensationEnable = 1;  // 0x2121

}  // namespace volcomp::canopen
