// The configuration file of volcomp-fw-linux (format and every key: docs/linux-board.md and
// firmware/linux/volcomp-fw-linux.conf). INI style:
//
//   [board]    node_id, heartbeat_ms, bitrate_kbit, tick_hz, axes (names in board order, e.g.
//              "X Y Z"), enable_input, serial_number
//   [can]      controller (CNC-side interface, the board's node), drives (drive-side interface;
//              empty = node only, no gateway), tx_queue, restart_on_bus_off
//   [gateway]  sync_cob_id, feedback (sync | latest)
//   [axis X]   one per axis: kind, units_per_step (mm or degrees per drive increment), invert,
//              target_pdo / actual_pdo (COB-ID:byte offset of 0x607A / 0x6064), max_correction,
//              max_rate, max_accel, home_position
//   [gpio]     backend (gpiod | fake | fake:STATE_FILE | none), consumer, debounce_ms, poll_ms,
//              and one line spec per wired line (home0..home5, enable, estop, drive_alarm,
//              write_enable, ready, compensating, fault)
//   [flash]    tables, settings (files), table_bank_kib, sector_bytes, sync, write_behind
//   [process]  realtime_priority (SCHED_FIFO 1..99, 0 = normal scheduling), lock_memory
//
// '#' and ';' start comments; numbers are decimal or 0x hex; booleans true/false/yes/no/on/off/1/0.
// Unknown sections and keys are errors (typos must not silently change the machine's behaviour).
//
// The values become the factory defaults of the board: settings stored over CAN (0x1010, only
// with a [flash] settings file) override the board/axis values at start-up until restored (0x1011).
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/firmware/settings.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/hal/linux/gpio_lines.hpp"

namespace volcomp::fw_linux {

enum class GpioBackendKind : uint8_t { kNone, kFake, kGpiod };

struct LinuxBoardConfig {
  firmware::BoardSettings settings;  // factory defaults of the board
  bool enable_input = false;         // compensation needs the enable input (else always enabled)
  uint32_t serial_number = 0;

  std::string controller_iface;  // required
  std::string drives_iface;      // empty: node only
  uint32_t tx_queue = 256;
  bool restart_on_bus_off = true;

  gateway::GatewayConfig gateway;  // own_node_id filled from settings.node_id

  GpioBackendKind gpio_backend = GpioBackendKind::kNone;
  std::string fake_state_file;  // fake:PATH
  hal::linux_board::GpioConfig gpio;
  uint32_t debounce_ms = 5;
  uint32_t io_poll_ms = 2;

  std::string table_file;     // required
  std::string settings_file;  // optional
  uint32_t table_bank_bytes = 512u * 1024u;
  uint32_t sector_bytes = 4096;
  bool flash_sync = true;
  bool flash_write_behind = true;

  uint32_t realtime_priority = 0;  // SCHED_FIFO priority of the process (0: SCHED_OTHER)
  bool lock_memory = false;        // mlockall: no page faults on the forwarding path
};

/// Why a configuration file was refused: where, and what is wrong there.
struct ConfigError {
  std::string source;   // the file (or the name given to ParseConfig)
  int line = 0;         // 1-based line; 0 when the problem is not on one line
  std::string message;  // e.g. "node_id: value above 127"
  /// "source:line: message", or "source: message" without a line.
  std::string ToString() const;
};

/// Parses `text` (named `source` in errors), starting from the defaults, and checks the result.
Expected<LinuxBoardConfig, ConfigError> ParseConfig(const std::string& text,
                                                    const std::string& source);
/// Reads and parses a file.
Expected<LinuxBoardConfig, ConfigError> LoadConfigFile(const std::string& path);
/// The effective configuration as text in the file's own format (--check-config).
std::string FormatConfig(const LinuxBoardConfig& config);

}  // namespace volcomp::fw_linux
