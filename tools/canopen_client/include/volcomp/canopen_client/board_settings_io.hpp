// The board's configuration objects over SDO (any NodeObjects: a real transport or the simulated
// bus): read all of them, write the ones that differ, store them (0x1010), and the settings-pending
// flag of the device state (0x2122) that tells whether what the objects read is in force.
//
// What the board exposes: a read of a configuration object gives its edited copy (what a store
// saves); the copy and the configuration in force differ exactly while the device state's
// "settings pending" bit is set (edited, or stored and not yet applied by NMT reset node). The
// configuration in force is one record, 0x2124 (the settings store's format, decoded with the
// firmware's own DeserializeSettings).
//
// Failures: kCommunication when the node does not answer (timeout, no adapter); the board's
// refusal of an access with the object and the board's reason otherwise (exit code 1).
// The objects and their file keys: lib/canopen setting_objects.hpp, hosted/ settings_ini.hpp.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/config/board_settings.hpp"

namespace volcomp::canopen_client {

/// Every stored configuration object of `node` (canopen::kSettingObjects), into settings that
/// start from the factory settings (fields without an object keep those).
Expected<BoardSettings> ReadSettings(NodeObjects& node);

/// True while the board's configuration objects differ from its configuration in force (0x2122
/// "settings pending").
Expected<bool> SettingsPending(NodeObjects& node);

/// The configuration the board runs with (0x2124); kInputInvalid when the record cannot be decoded.
Expected<BoardSettings> ReadSettingsInForce(NodeObjects& node);

struct Difference {
  canopen::ObjectId id;
  int64_t from = 0;  // in `a`
  int64_t to = 0;    // in `b`
};

/// The stored configuration objects whose values differ between `a` and `b`, in dictionary order.
std::vector<Difference> Differences(const BoardSettings& a, const BoardSettings& b);

/// "2015:2 max_correction (axis Y) 1000 -> 800": one difference for people.
std::string DescribeDifference(const Difference& d, const BoardSettings& names);

/// Writes each object of `changes` with its `to` value (after EnsureWritable), counting the
/// objects written in `*written`. Stops at the first refusal (naming the object and the board's
/// reason).
Outcome WriteObjects(NodeObjects& node, const std::vector<Difference>& changes, size_t* written);

/// Stores the configuration objects (0x1010:1 = "save"); the board validates them as a whole and
/// refuses an inconsistent set (with the reason).
Outcome StoreSettings(NodeObjects& node);

/// `r`'s value, or its failure explained as `what` (table_staging.hpp Explain()).
template <typename T>
Expected<T> Explained(SdoExpected<T> r, const std::string& what) {
  if (!r.ok()) return Fail(Failure(Explain(r.error(), what)));
  if constexpr (std::is_void_v<T>) {
    return Expected<T>();
  } else {
    return std::move(r).value();
  }
}

}  // namespace volcomp::canopen_client
