// The stored configuration objects, expanded from the VOLCOMP_OD_SETTING rows of od_entries.def.
#include "volcomp/canopen/setting_objects.hpp"

#include <type_traits>

#include "volcomp/canopen/node_defaults.hpp"

namespace volcomp::canopen {
namespace {

template <class T>
constexpr int64_t FieldValue(T v) {
  if constexpr (std::is_enum_v<T>) {
    return static_cast<int64_t>(static_cast<std::underlying_type_t<T>>(v));
  } else {
    return static_cast<int64_t>(v);
  }
}

template <class T>
constexpr void SetField(T& field, int64_t v) {
  field = static_cast<T>(v);
}

template <class T>
constexpr bool IsEnum(const T&) {
  return std::is_enum_v<T>;
}

constexpr BoardSettings kProbe{};

// clang-format off
#define VOLCOMP_OD_BINDING(id, field, axis, channel)                                             \
  {ObjectId::id, axis, channel, IsEnum(kProbe.field),                                            \
   [](const BoardSettings& s) { return FieldValue(s.field); },                                   \
   [](BoardSettings& s, int64_t v) { SetField(s.field, v); }},
#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name)
#define VOLCOMP_OD_SETTING(id, index, sub, type, limits, def, field, key, name)                \
  VOLCOMP_OD_BINDING(id, field, kBoardSetting, kNoChannel)
#define VOLCOMP_OD_AXIS_SETTING(id, index, type, limits, field, key, name)                     \
  VOLCOMP_OD_BINDING(id##1, board.axis[0].field, 0, kNoChannel)                                         \
  VOLCOMP_OD_BINDING(id##2, board.axis[1].field, 1, kNoChannel)                                         \
  VOLCOMP_OD_BINDING(id##3, board.axis[2].field, 2, kNoChannel)                                         \
  VOLCOMP_OD_BINDING(id##4, board.axis[3].field, 3, kNoChannel)                                         \
  VOLCOMP_OD_BINDING(id##5, board.axis[4].field, 4, kNoChannel)                                         \
  VOLCOMP_OD_BINDING(id##6, board.axis[5].field, 5, kNoChannel)
#define VOLCOMP_OD_CHANNEL_SETTING(id, index, type, limits, field, key, name)                  \
  VOLCOMP_OD_BINDING(id##1, temperature[0].field, kBoardSetting, 0)                         \
  VOLCOMP_OD_BINDING(id##2, temperature[1].field, kBoardSetting, 1)                         \
  VOLCOMP_OD_BINDING(id##3, temperature[2].field, kBoardSetting, 2)                         \
  VOLCOMP_OD_BINDING(id##4, temperature[3].field, kBoardSetting, 3)                         \
  VOLCOMP_OD_BINDING(id##5, temperature[4].field, kBoardSetting, 4)                         \
  VOLCOMP_OD_BINDING(id##6, temperature[5].field, kBoardSetting, 5)                         \
  VOLCOMP_OD_BINDING(id##7, temperature[6].field, kBoardSetting, 6)                         \
  VOLCOMP_OD_BINDING(id##8, temperature[7].field, kBoardSetting, 7)
}  // namespace

// Declared extern in the header: constexpr here so the index below is built at compile time.
constexpr SettingObject kSettingObjects[] = {
#include "volcomp/canopen/od_entries.def"  // NOLINT(build/include)
};

namespace {
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
#undef VOLCOMP_OD_SETTING
#undef VOLCOMP_OD_AXIS_SETTING
#undef VOLCOMP_OD_CHANNEL_SETTING
#undef VOLCOMP_OD_BINDING
// clang-format on

constexpr size_t kCount = sizeof(kSettingObjects) / sizeof(kSettingObjects[0]);
static_assert(kCount < 0xFF, "the index below holds table positions in a byte");
static_assert(table::kMaxAxes == 6, "the per-axis rows expand to six elements");
static_assert(thermal::kMaxChannels == 8, "the per-channel rows expand to eight elements");

// Table position by ObjectId (0xFF: not a setting), so the dictionary's reads and writes find a
// field in constant time.
struct Index {
  uint8_t of[static_cast<size_t>(ObjectId::kCount)];
};
constexpr Index MakeIndex() {
  Index x{};
  for (uint8_t& i : x.of) i = 0xFF;
  for (size_t i = 0; i < kCount; ++i) {
    x.of[static_cast<size_t>(kSettingObjects[i].id)] = static_cast<uint8_t>(i);
  }
  return x;
}
constexpr Index kIndex = MakeIndex();

}  // namespace

const size_t kSettingObjectCount = kCount;

const SettingObject* FindSetting(ObjectId id) {
  const uint8_t i = kIndex.of[static_cast<size_t>(id)];
  return i == 0xFF ? nullptr : &kSettingObjects[i];
}

}  // namespace volcomp::canopen
