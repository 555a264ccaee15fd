// Little-endian loads and stores at any alignment (the table image and CAN payloads are LE).
#pragma once

#include <cstdint>

namespace volcomp {

inline uint16_t LoadLe16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
inline uint32_t LoadLe32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
         (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}
inline int32_t LoadLeI32(const uint8_t* p) { return static_cast<int32_t>(LoadLe32(p)); }
inline float LoadLeF32(const uint8_t* p) {
  const uint32_t bits = LoadLe32(p);
  float f;
  __builtin_memcpy(&f, &bits, sizeof f);
  return f;
}

inline void StoreLe16(uint8_t* p, uint16_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}
inline void StoreLe32(uint8_t* p, uint32_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
  p[2] = static_cast<uint8_t>(v >> 16);
  p[3] = static_cast<uint8_t>(v >> 24);
}
inline void StoreLeF32(uint8_t* p, float f) {
  uint32_t bits;
  __builtin_memcpy(&bits, &f, sizeof bits);
  StoreLe32(p, bits);
}

}  // namespace volcomp
