// The stored configuration objects, expanded from the bindings in od_entries.def.
#include "volcomp/board_ini/setting_objects.hpp"

#include <cstdio>
#include <type_traits>

namespace volcomp::board_ini {
namespace {

using canopen::DataType;
using canopen::ObjectId;
using firmware::BoardSettings;

template <class T>
int64_t FieldValue(T v) {
  if constexpr (std::is_enum_v<T>) {
    return static_cast<int64_t>(static_cast<std::underlying_type_t<T>>(v));
  } else {
    return static_cast<int64_t>(v);
  }
}

template <class T>
void SetField(T& field, int64_t v) {
  field = static_cast<T>(v);
}

std::vector<SettingObject> Expand() {
  std::vector<SettingObject> out = {
      {ObjectId::kEmcyInhibitTime,
       [](const BoardSettings& s) { return FieldValue(s.emcy_inhibit_100us); },
       [](BoardSettings& s, int64_t v) { SetField(s.emcy_inhibit_100us, v); }},
      {ObjectId::kHeartbeatTime, [](const BoardSettings& s) { return FieldValue(s.heartbeat_ms); },
       [](BoardSettings& s, int64_t v) { SetField(s.heartbeat_ms, v); }},
  };
#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name)
#define VOLCOMP_OD_SETTING(id, index, sub, type, limits, def, field, name)                 \
  out.push_back({ObjectId::id, [](const BoardSettings& s) { return FieldValue(s.field); }, \
                 [](BoardSettings& s, int64_t v) { SetField(s.field, v); }});
#include "volcomp/canopen/od_entries.def"  // NOLINT(build/include)
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
#undef VOLCOMP_OD_SETTING
  return out;
}

}  // namespace

const std::vector<SettingObject>& SettingObjects() {
  static const std::vector<SettingObject> kObjects = Expand();
  return kObjects;
}

const SettingObject* FindSettingObject(ObjectId id) {
  for (const SettingObject& o : SettingObjects()) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

int64_t FromRaw(const canopen::ObjectEntry& e, uint32_t raw) {
  switch (e.type) {
    case DataType::kInteger8:
      return static_cast<int8_t>(raw);
    case DataType::kInteger16:
      return static_cast<int16_t>(raw);
    case DataType::kInteger32:
      return static_cast<int32_t>(raw);
    case DataType::kUnsigned8:
    case DataType::kBoolean:
      return raw & 0xFFu;
    case DataType::kUnsigned16:
      return raw & 0xFFFFu;
    default:
      return raw;
  }
}

std::string LimitViolation(const canopen::ObjectEntry& e, int64_t v) {
  int64_t low = 0, high = 0xFFFFFFFFll;
  switch (e.type) {
    case DataType::kBoolean:
      high = 1;
      break;
    case DataType::kInteger8:
      low = -128;
      high = 127;
      break;
    case DataType::kInteger16:
      low = -32768;
      high = 32767;
      break;
    case DataType::kInteger32:
      low = -2147483648ll;
      high = 2147483647ll;
      break;
    case DataType::kUnsigned8:
      high = 0xFF;
      break;
    case DataType::kUnsigned16:
      high = 0xFFFF;
      break;
    default:
      break;
  }
  if (e.limited) {
    low = e.low_limit > low ? e.low_limit : low;
    high = e.high_limit < high ? e.high_limit : high;
  }
  if (v < low) return "below the lowest value " + std::to_string(low);
  if (v > high) return "above the highest value " + std::to_string(high);
  return "";
}

std::string ObjectAddress(const canopen::ObjectEntry& e) {
  char text[16];
  std::snprintf(text, sizeof text, "%04X:%u", e.index, e.sub);
  return text;
}

BoardSettings FactorySettings() { return BoardSettings(); }

}  // namespace volcomp::board_ini
