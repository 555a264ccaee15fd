// How the `config` commands name and show the board's configuration objects (the settings file's
// keys, units and value forms, hosted/settings_ini.hpp), and what the board reads back.
#pragma once

#include <string>

#include "command.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::cli {

/// The axis a configuration object belongs to ("X", or its number "4" beyond the axis count), ""
/// for board objects and the temperature channels' objects.
std::string AxisOf(const canopen::ObjectEntry& e, const BoardSettings& s);
/// The temperature channel (1..8) of a channel object (0x2158-0x215D), 0 for the others.
uint8_t ChannelOf(const canopen::ObjectEntry& e);
/// Its key in the configuration file ("max_correction", "axes (name)", "axes (count)").
std::string KeyName(const canopen::ObjectEntry& e);
/// Its value as the file writes it ("linear", "0.001", "-5000").
std::string ValueText(const canopen::ObjectEntry& e, int64_t value);
/// Its unit and meaning, "" for objects without a key.
std::string UnitOf(const canopen::ObjectEntry& e);

/// The axes of `s` whose direction switch acceleration (0x2020) takes effect below the configured
/// value at the board's compensation rate (DirectionSwitchAccelInEffect, lib/config): per axis
/// `object`, `axis`, `configured`, `in_effect` (steps/s^2), `compensation_hz` and `bound`
/// ("compensation period": below one step per period squared; "drive rate": reaches the rate the
/// drive has beyond the input within one period). Empty when every value takes effect.
JsonValue SwitchAccelBounds(const BoardSettings& s);
/// One such axis as a line of text.
std::string SwitchAccelBoundText(const JsonValue& x);

/// What it means that settings are pending.
const char* PendingNote();

/// The board's configuration objects and whether they are pending (not in force).
struct BoardConfiguration {
  BoardSettings settings;
  bool pending = false;
};
Expected<BoardConfiguration> ReadConfiguration(canopen_client::NodeObjects& node);

}  // namespace volcomp::cli
