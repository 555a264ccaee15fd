// Building CAN frames field by field in tests.
#pragma once

#include <cstdint>
#include <vector>

#include "volcomp/can/can_frame.hpp"

namespace volcomp::testing {

/// A frame from its fields; dlc is the data size unless given (a remote frame has a length but no
/// data, and a DLC above 8 is what some tests must see refused).
inline CanFrame Frame(uint32_t id, bool ext, bool rtr, std::vector<uint8_t> data, int dlc = -1) {
  CanFrame f;
  f.id = id;
  f.extended = ext;
  f.rtr = rtr;
  f.dlc = static_cast<uint8_t>(dlc >= 0 ? dlc : static_cast<int>(data.size()));
  for (size_t i = 0; i < data.size() && i < sizeof f.data; ++i) f.data[i] = data[i];
  return f;
}

}  // namespace volcomp::testing
