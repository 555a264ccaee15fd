// The native component's load-time configuration, from `loadrt volcomp` parameters: instance
// names (count= or names=, as components made with halcompile), linear units (units=, the
// value of [TRAJ]LINEAR_UNITS) and which table axis each joint channel belongs to (axes=, e.g.
// XYYZ for a gantry whose two Y joints share the table's Y correction). Pure functions of
// strings, run at `loadrt` (outside the servo thread); Failures carry the message for the user.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "native/native_table.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::linuxcnc {

/// Most instances one `loadrt` makes, and most joint channels an instance has.
inline constexpr int kMaxInstances = 8;
inline constexpr int kMaxChannels = 9;

/// Instance names: `names` (given) or "volcomp.0" .. "volcomp.<count-1>" (count 0: one).
/// Refuses both at once, more than kMaxInstances, and names HAL would not take.
Expected<std::vector<std::string>> InstanceNames(int count, const std::vector<std::string>& names);

/// Millimetres per machine unit for a linear units value (hosted/linuxcnc_units.hpp: mm, inch
/// and their other spellings, any case, or units per mm); empty means mm.
Expected<double> ParseLinearUnits(const std::string& text);

/// Joint channels of an instance and the table axis of each.
struct ChannelMap {
  uint8_t count = 0;
  uint8_t axis_of[kMaxChannels] = {};
  /// Per table axis, the channel whose joint position is the axis's machine position (the first
  /// channel naming the axis: a gantry's second joint follows the first).
  uint8_t position_channel[table::kMaxAxes] = {};
};

/// `axes`: one letter per joint channel (channel j = joint j in the recipes), each an axis of
/// `table`, every table axis at least once; empty: the table's axes in order.
Expected<ChannelMap> MapChannels(const std::string& axes, const NativeTable& table);

}  // namespace volcomp::linuxcnc
