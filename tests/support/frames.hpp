// Compact frame notation for protocol tests: F(0x610, "C600210114000000") and ToString().
#pragma once

#include <cstdio>
#include <string>

#include "volcomp/can/can_frame.hpp"

namespace volcomp::testing {

inline CanFrame F(uint32_t id, const std::string& hex) {
  CanFrame f;
  f.id = id;
  f.dlc = static_cast<uint8_t>(hex.size() / 2);
  for (size_t i = 0; i < f.dlc; ++i) {
    f.data[i] = static_cast<uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
  }
  return f;
}

inline std::string ToString(const CanFrame& f) {
  char buf[48];
  int n = std::snprintf(buf, sizeof buf, "%03X#", f.id);
  for (int i = 0; i < f.dlc; ++i) n += std::snprintf(buf + n, sizeof buf - n, "%02X", f.data[i]);
  return buf;
}

}  // namespace volcomp::testing
