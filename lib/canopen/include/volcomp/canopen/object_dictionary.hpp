// The object dictionary's structure (od_entries.def): indices, types, access, defaults, names.
// Values live elsewhere (the node and the application, see object_values.hpp); this table is what
// the SDO server checks every access against, what the PC tool uses for object addresses, and what
// the EDS generator writes.
#pragma once

#include <cstddef>
#include <cstdint>

namespace volcomp::canopen {

/// CiA 301 data types (EDS DataType codes).
enum class DataType : uint16_t {
  kBoolean = 0x0001,
  kInteger8 = 0x0002,
  kInteger16 = 0x0003,
  kInteger32 = 0x0004,
  kUnsigned8 = 0x0005,
  kUnsigned16 = 0x0006,
  kUnsigned32 = 0x0007,
  kVisibleString = 0x0009,
  kDomain = 0x000F,
};

enum class Access : uint8_t { kRo, kWo, kRw, kConst };
enum class ObjectKind : uint8_t { kVar = 7, kArray = 8, kRecord = 9 };  // EDS ObjectType codes

/// Every (sub-)entry by name.
enum class ObjectId : uint16_t {
#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name) id,
#include "volcomp/canopen/od_entries.def"  // NOLINT(build/include)
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
  kCount
};

/// Values that must be written to trigger an action (ASCII, little-endian).
inline constexpr uint32_t kSaveSignature = 0x65766173;    // "save" to 0x1010:1 (CiA 301)
inline constexpr uint32_t kLoadSignature = 0x64616F6C;    // "load" to 0x1011:1 (CiA 301)
inline constexpr uint32_t kUnlockSignature = 0x6B6C6E75;  // "unlk" to 0x2110 (write access)

// The wide fields first: 40 bytes an entry on the MCU rather than 56 with the padding the
// declaration order (id, index, sub, type, access, default, name, limits) would need.
struct ObjectEntry {
  int64_t default_value;  // what a board without stored settings reports
  int64_t low_limit;      // writes outside [low_limit, high_limit] are refused (when `limited`)
  int64_t high_limit;
  const char* name;
  ObjectId id;
  uint16_t index;
  DataType type;
  uint8_t sub;
  Access access;
  bool limited;
  bool pdo_mappable;  // a produced ro numeric value (TPDO) or a command (RPDO); EDS PDOMapping
};

struct ObjectHeader {
  uint16_t index;
  ObjectKind kind;
  const char* name;
};

/// All entries in (index, sub) order.
extern const ObjectEntry kObjectEntries[];
extern const size_t kObjectEntryCount;
/// All objects in index order.
extern const ObjectHeader kObjectHeaders[];
extern const size_t kObjectHeaderCount;

/// The entry for (index, sub), or null. `index_exists` (optional) reports whether the index exists
/// at all (to tell "no object" from "no sub-index").
const ObjectEntry* FindEntry(uint16_t index, uint8_t sub, bool* index_exists = nullptr);
/// The entry of an id (always valid for ids below kCount).
const ObjectEntry& Entry(ObjectId id);

/// Size in bytes of fixed-size types; 0 for strings and domains.
constexpr uint32_t FixedSize(DataType t) {
  switch (t) {
    case DataType::kBoolean:
    case DataType::kInteger8:
    case DataType::kUnsigned8:
      return 1;
    case DataType::kInteger16:
    case DataType::kUnsigned16:
      return 2;
    case DataType::kInteger32:
    case DataType::kUnsigned32:
      return 4;
    default:
      return 0;
  }
}

constexpr bool Readable(Access a) { return a != Access::kWo; }
constexpr bool Writable(Access a) { return a == Access::kWo || a == Access::kRw; }

/// The values a write to a numeric entry may carry: its type's range, narrowed by the entry's
/// limits (the board refuses others; the EDS lists the limits as LowLimit/HighLimit).
struct ValueRange {
  int64_t low = 0;
  int64_t high = 0;
};
constexpr ValueRange EntryRange(const ObjectEntry& e) {
  ValueRange r;
  switch (e.type) {
    case DataType::kBoolean:
      r = {0, 1};
      break;
    case DataType::kInteger8:
      r = {-128, 127};
      break;
    case DataType::kInteger16:
      r = {-32768, 32767};
      break;
    case DataType::kInteger32:
      r = {-2147483648ll, 2147483647ll};
      break;
    case DataType::kUnsigned8:
      r = {0, 0xFF};
      break;
    case DataType::kUnsigned16:
      r = {0, 0xFFFF};
      break;
    case DataType::kUnsigned32:
      r = {0, 0xFFFFFFFFll};
      break;
    default:
      break;
  }
  if (e.limited) {
    r.low = e.low_limit > r.low ? e.low_limit : r.low;
    r.high = e.high_limit < r.high ? e.high_limit : r.high;
  }
  return r;
}

/// A numeric entry's value from its little-endian bytes as read or written (`raw`: up to 4 bytes,
/// zero-filled): sign-extended for the signed types, masked to the size of the unsigned ones.
constexpr int64_t EntryValue(const ObjectEntry& e, uint32_t raw) {
  switch (e.type) {
    case DataType::kInteger8:
      return static_cast<int8_t>(raw);
    case DataType::kInteger16:
      return static_cast<int16_t>(raw);
    case DataType::kInteger32:
      return static_cast<int32_t>(raw);
    case DataType::kBoolean:
    case DataType::kUnsigned8:
      return raw & 0xFFu;
    case DataType::kUnsigned16:
      return raw & 0xFFFFu;
    default:
      return raw;
  }
}

/// The (index, sub) of axis `axis` (0-based) in a per-axis array whose axis-1 entry is `first`.
inline const ObjectEntry& AxisEntry(ObjectId first, uint8_t axis) {
  return Entry(static_cast<ObjectId>(static_cast<uint16_t>(first) + axis));
}

}  // namespace volcomp::canopen
