// The configuration file of volcomp-fw-linux (every key: docs/linux-board.md, example
// firmware/linux_board/volcomp-fw-linux.conf). [board] and [axis NAME] are the board's settings,
// read and written by the one settings codec (hosted/ settings_ini.hpp, the keys of the PC tool's
// board file) with this board's keys beside them (enable_input, serial_number; invert, target_pdo,
// actual_pdo); [can], [gateway], [gpio], [flash], [sensors] and [process] are this board's alone.
//
// Unknown sections and keys are errors (a typo must not silently change the machine); every error
// names the file and line (ConfigError). The values are the board's factory defaults: settings
// stored over CAN (0x1010, with a [flash] settings file) override them until restored (0x1011).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "volcomp/config/board_settings.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/hal/linux/gpio_lines.hpp"
#include "volcomp/hosted/ini.hpp"

namespace volcomp::linux_board {

enum class GpioBackendKind : uint8_t { kNone, kFake, kGpiod };

/// The board settings a file starts from: the factory settings at a 1 kHz tick.
BoardSettings LinuxBoardDefaults();

struct LinuxBoardConfig {
  BoardSettings settings = LinuxBoardDefaults();  // factory defaults of the board
  bool enable_input = false;  // compensation needs the enable input (else always enabled)
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

  // [sensors]: temperature_files[n] is temperature channel n's file (temperature_file.N, N = n + 1;
  // empty: none), read every temperature_period_ms (temperature_files.hpp).
  std::array<std::string, thermal::kMaxChannels> temperature_files;
  uint32_t temperature_period_ms = 500;

  uint32_t realtime_priority = 0;  // SCHED_FIFO priority of the process (0: SCHED_OTHER)
  bool lock_memory = false;        // mlockall: no page faults on the forwarding path
};

/// Why a configuration file was refused: where (source, line), and what is wrong there.
using ConfigError = hosted::IniError;

/// Parses `text` (named `source` in errors), starting from the defaults, and checks the result.
Expected<LinuxBoardConfig, ConfigError> ParseConfig(const std::string& text,
                                                    const std::string& source);
/// Reads and parses a file.
Expected<LinuxBoardConfig, ConfigError> LoadConfigFile(const std::string& path);
/// The effective configuration as text in the file's own format (--check-config).
std::string FormatConfig(const LinuxBoardConfig& config);

}  // namespace volcomp::linux_board
