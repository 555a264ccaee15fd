// The board's stored configuration objects as fields of firmware::BoardSettings: every
// VOLCOMP_OD_SETTING row of od_entries.def (bound there to its field, expanded here as the
// firmware expands it) and the two communication parameters a store (0x1010) saves with them,
// 0x1015 (EMCY inhibit time) and 0x1017 (heartbeat). What `volcomp config` reads, writes and
// compares. BoardSettings fields without an object (pulse clock, input counter width, input
// direction) are not configuration a PC can change and keep their defaults here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/firmware/settings.hpp"

namespace volcomp::board_ini {

struct SettingObject {
  canopen::ObjectId id;
  int64_t (*get)(const firmware::BoardSettings& s);
  void (*set)(firmware::BoardSettings& s, int64_t value);
};

/// Every stored configuration object in dictionary order: 0x1015, 0x1017, 0x2000:1-4,
/// 0x2010:1-6 ... 0x201E:1-6.
const std::vector<SettingObject>& SettingObjects();

/// The object of `id`, or null when `id` is not a stored configuration object.
const SettingObject* FindSettingObject(canopen::ObjectId id);

/// The number an SDO read of `e` gave (`raw`, little-endian in the entry's size), sign-extended
/// for the signed types.
int64_t FromRaw(const canopen::ObjectEntry& e, uint32_t raw);

/// Why `value` cannot be written to `e` ("above the highest value 127"), or "" when it can: the
/// entry's dictionary limits (the ones the board checks before a write) and the range of its data
/// type (a value outside it would be truncated on the way).
std::string LimitViolation(const canopen::ObjectEntry& e, int64_t value);

/// "2015:1": the object's index (hex) and sub-index, as `volcomp sdo` takes it.
std::string ObjectAddress(const canopen::ObjectEntry& e);

/// The factory settings: what a board without stored settings runs with.
firmware::BoardSettings FactorySettings();

}  // namespace volcomp::board_ini
