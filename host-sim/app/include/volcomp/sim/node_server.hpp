// `volcomp-sim node`: the real firmware (BoardApp on the mock HAL) on a simulated CAN bus that
// spends real frame time at the chosen bit rate, served in real time to an external client over
// SLCAN on TCP or a pty, or bridged to a SocketCAN interface.
#pragma once

#include <string>
#include <vector>

namespace volcomp::sim {

/// Parses the command-line options and serves until SIGINT/SIGTERM or --duration. Returns the
/// process exit code. Throws std::runtime_error for bad options or unavailable endpoints.
int RunNodeServer(const std::vector<std::string>& args);

}  // namespace volcomp::sim
