// The object dictionary tables, expanded from od_entries.def.
#include "volcomp/canopen/object_dictionary.hpp"

#include "volcomp/canopen/node_defaults.hpp"
#include "volcomp/config/board_config.hpp"

// The names serve the EDS file and the host tools' messages. A cross build (the MCU images,
// VOLCOMP_OD_NAMES=0: lib/CMakeLists.txt) leaves them empty: the node answers by index and
// sub-index, and their 9 KB of text would crowd the 76 KB application region (docs/mcu-target.md).
#if !defined(VOLCOMP_OD_NAMES) || VOLCOMP_OD_NAMES
#define VOLCOMP_OD_NAME(text) text
#else
#define VOLCOMP_OD_NAME(text) ""
#endif

namespace volcomp::canopen {

const ObjectEntry kObjectEntries[] = {
// Fields in ObjectEntry's order: default, low, high, name, id, index, type, sub, access, limited,
// pdo_mappable.
#define VOLCOMP_OD_LIMITS(low, high) (low, high, true)
#define VOLCOMP_OD_NO_LIMITS (0, 0, false)
#define VOLCOMP_OD_LIMIT_LOW(low, high, limited) low
#define VOLCOMP_OD_LIMIT_HIGH(low, high, limited) high
#define VOLCOMP_OD_LIMIT_FLAG(low, high, limited) limited
#define VOLCOMP_OD_ROW(id, index, sub, type, access, def, name, low, high, limited, mappable) \
  {def,                                                                                       \
   low,                                                                                       \
   high,                                                                                      \
   VOLCOMP_OD_NAME(name),                                                                     \
   ObjectId::id,                                                                              \
   index,                                                                                     \
   DataType::type,                                                                            \
   sub,                                                                                       \
   Access::access,                                                                            \
   limited,                                                                                   \
   mappable},
#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name) \
  VOLCOMP_OD_ROW(id, index, sub, type, access, def, name, 0, 0, false, false)
#define VOLCOMP_OD_VALUE(id, index, sub, type, access, def, source, name) \
  VOLCOMP_OD_ROW(id, index, sub, type, access, def, name, 0, 0, false,    \
                 Access::access == Access::kRo && FixedSize(DataType::type) != 0)
#define VOLCOMP_OD_COMMAND(id, index, sub, type, def, source, name) \
  VOLCOMP_OD_ROW(id, index, sub, type, kRw, def, name, 0, 0, false, true)
#define VOLCOMP_OD_SETTING(id, index, sub, type, limits, def, field, key, name) \
  VOLCOMP_OD_ROW(id, index, sub, type, kRw, static_cast<int64_t>(def), name,    \
                 VOLCOMP_OD_LIMIT_LOW limits, VOLCOMP_OD_LIMIT_HIGH limits,     \
                 VOLCOMP_OD_LIMIT_FLAG limits, false)
#include "volcomp/canopen/od_entries.def"
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
#undef VOLCOMP_OD_VALUE
#undef VOLCOMP_OD_COMMAND
#undef VOLCOMP_OD_SETTING
#undef VOLCOMP_OD_LIMITS
#undef VOLCOMP_OD_NO_LIMITS
#undef VOLCOMP_OD_LIMIT_LOW
#undef VOLCOMP_OD_LIMIT_HIGH
#undef VOLCOMP_OD_LIMIT_FLAG
#undef VOLCOMP_OD_ROW
};
const size_t kObjectEntryCount = sizeof(kObjectEntries) / sizeof(kObjectEntries[0]);

const ObjectHeader kObjectHeaders[] = {
#define VOLCOMP_OD_OBJECT(index, kind, name) {index, ObjectKind::kind, VOLCOMP_OD_NAME(name)},
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name)
#include "volcomp/canopen/od_entries.def"
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
};
const size_t kObjectHeaderCount = sizeof(kObjectHeaders) / sizeof(kObjectHeaders[0]);

static_assert(sizeof(kObjectEntries) / sizeof(kObjectEntries[0]) ==
                  static_cast<size_t>(ObjectId::kCount),
              "one entry per ObjectId");

const ObjectEntry* FindEntry(uint16_t index, uint8_t sub, bool* index_exists) {
  // Binary search on (index, sub); the table is sorted (checked by a unit test).
  const uint32_t key = (uint32_t{index} << 8) | sub;
  size_t lo = 0, hi = kObjectEntryCount;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    const uint32_t k = (uint32_t{kObjectEntries[mid].index} << 8) | kObjectEntries[mid].sub;
    if (k < key) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  const bool hit =
      lo < kObjectEntryCount && kObjectEntries[lo].index == index && kObjectEntries[lo].sub == sub;
  if (index_exists != nullptr) {
    // The insertion point is next to the index's entries if it has any.
    *index_exists = hit || (lo < kObjectEntryCount && kObjectEntries[lo].index == index) ||
                    (lo > 0 && kObjectEntries[lo - 1].index == index);
  }
  return hit ? &kObjectEntries[lo] : nullptr;
}

const ObjectEntry& Entry(ObjectId id) { return kObjectEntries[static_cast<size_t>(id)]; }

}  // namespace volcomp::canopen
