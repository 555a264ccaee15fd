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
// Errors: tools::CommunicationError when the node does not answer (timeout, no adapter);
// tools::InputError with the object and the board's reason when the board refuses an access.
// The objects and their file keys: lib/canopen setting_objects.hpp, hosted/ settings_ini.hpp.
#pragma once

#include <string>
#include <vector>

#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/config/board_settings.hpp"

namespace volcomp::canopen_client {

/// Every stored configuration object of `node` (canopen::kSettingObjects), into settings that
/// start from the factory settings (fields without an object keep those).
BoardSettings ReadSettings(NodeObjects& node);

/// True while the board's configuration objects differ from its configuration in force (0x2122
/// "settings pending").
bool SettingsPending(NodeObjects& node);

/// The configuration the board runs with (0x2124). InputError when the record cannot be decoded.
BoardSettings ReadSettingsInForce(NodeObjects& node);

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
/// objects written in `*written`. Stops at the first refusal (InputError naming the object and the
/// board's reason).
void WriteObjects(NodeObjects& node, const std::vector<Difference>& changes, size_t* written);

/// Stores the configuration objects (0x1010:1 = "save"); the board validates them as a whole and
/// refuses an inconsistent set (InputError with the reason).
void StoreSettings(NodeObjects& node);

/// Throws CommunicationError (no answer) or InputError (refused: `what`, the board's reason).
void Require(const SdoResult& r, const std::string& what);

}  // namespace volcomp::canopen_client
