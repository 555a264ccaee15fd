// The board's stored configuration objects, expanded from the VOLCOMP_OD_SETTING rows of
// od_entries.def, each bound to its BoardSettings field (lib/config board_settings.hpp): one table
// for the firmware's dictionary (reads and writes of the configuration objects), the configuration
// files' codec (hosted/ settings_ini.hpp, which takes the rows' file keys) and the PC tool's
// transfer of the settings. Freestanding, constant data.
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/config/board_settings.hpp"

namespace volcomp::canopen {

/// Not a per-axis setting.
inline constexpr uint8_t kBoardSetting = 0xFF;
/// Not a per-channel setting.
inline constexpr uint8_t kNoChannel = 0x7F;

struct SettingObject {
  ObjectId id;
  uint8_t axis;            // per-axis arrays: the element's axis (0-based); else kBoardSetting
  uint8_t channel : 7;     // per-channel arrays (0x2158-0x215D): the channel (0-based); else
                           // kNoChannel
  uint8_t enumerated : 1;  // an enum field: an out-of-range write is invalid, not too high or low
  int64_t (*get)(const BoardSettings& s);
  void (*set)(BoardSettings& s, int64_t value);
};

/// Every stored configuration object in dictionary order: 0x1015, 0x1017, 0x2000:1-4,
/// 0x2010:1-6 ... 0x2020:1-6, 0x2158:1-8 ... 0x215D:1-8.
extern const SettingObject kSettingObjects[];
extern const size_t kSettingObjectCount;

/// kSettingObjects as a range: `for (const SettingObject& s : SettingObjects())`.
class SettingObjectList {
 public:
  const SettingObject* begin() const { return kSettingObjects; }
  const SettingObject* end() const { return kSettingObjects + kSettingObjectCount; }
  size_t size() const { return kSettingObjectCount; }
};
inline SettingObjectList SettingObjects() { return SettingObjectList(); }

/// The setting of `id`, or null when `id` is not a stored configuration object (constant time).
const SettingObject* FindSetting(ObjectId id);

}  // namespace volcomp::canopen
