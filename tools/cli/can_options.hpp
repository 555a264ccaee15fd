// What every CAN command shares: the adapter and node it talks to (--can, --node, --log,
// --timeout-ms; their help is CanOptions() in option_groups.hpp) and the session it opens.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "command.hpp"
#include "option_groups.hpp"
#include "volcomp/canopen_client/can_session.hpp"

namespace volcomp::cli {

/// Which adapter and node a command talks to, and how long it waits for each answer.
struct CanConnection {
  std::string spec;
  uint8_t node = 0x10;
  std::string log;
  uint32_t timeout_ms = 1000;
};

/// Reads the CanOptions() group; a missing --can or a value out of range is a usage failure.
Expected<CanConnection> ParseCanOptions(Args& args);

/// Opens the adapter and the session; every failure to open is kCommunication (exit 3).
Expected<std::unique_ptr<canopen_client::CanSession>> OpenSession(const CanConnection& can);

/// `--json` of the table commands (upload, verify, activate, deactivate).
const Options& JsonResultOption();

}  // namespace volcomp::cli
