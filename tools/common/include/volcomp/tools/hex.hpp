// Hexadecimal text for CRCs, abort codes and identifiers in messages and reports.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace volcomp::tools {

/// "0x%08X", e.g. Hex32(0x08000022) == "0x08000022".
inline std::string Hex32(uint32_t value) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", value);
  return b;
}

}  // namespace volcomp::tools
