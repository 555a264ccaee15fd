// How the `config` commands name and show the board's configuration objects (the settings file's
// keys, units and value forms, hosted/settings_ini.hpp), and what the board reads back.
#pragma once

#include <string>

#include "command.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::cli {

/// The axis a configuration object belongs to ("X", or its number "4" beyond the axis count), ""
/// for board objects.
std::string AxisOf(const canopen::ObjectEntry& e, const BoardSettings& s);
/// Its key in the configuration file ("max_correction", "axes (name)", "axes (count)").
std::string KeyName(const canopen::ObjectEntry& e);
/// Its value as the file writes it ("linear", "0.001", "-5000").
std::string ValueText(const canopen::ObjectEntry& e, int64_t value);
/// Its unit and meaning, "" for objects without a key.
std::string UnitOf(const canopen::ObjectEntry& e);

/// What it means that settings are pending.
const char* PendingNote();

/// The board's configuration objects and whether they are pending (not in force).
struct BoardConfiguration {
  BoardSettings settings;
  bool pending = false;
};
Expected<BoardConfiguration> ReadConfiguration(canopen_client::NodeObjects& node);

}  // namespace volcomp::cli
