// What a board without stored settings uses for its CANopen node and bus-side switches: the node
// settings' defaults (lib/config board_settings.hpp, here under their protocol names) and of the
// dictionary entries bound to them (od_entries.def, hence the EDS DefaultValue).
#pragma once

#include <cstdint>

#include "volcomp/config/board_settings.hpp"

namespace volcomp::canopen {

using ::volcomp::kDefaultBitrateKbit;                     // 0x2000:2
using ::volcomp::kDefaultEmcyInhibit100us;                // 0x1015
using ::volcomp::kDefaultHeartbeatMs;                     // 0x1017 (0 = off)
using ::volcomp::kDefaultNodeId;                          // 0x2000:1
inline constexpr uint8_t kDefaultCompensationEnable = 1;  // 0x2121

}  // namespace volcomp::canopen
