// The simulated node (`volcomp-sim node`): the real firmware (BoardApp on the mock HAL) on a
// simulated CAN bus that spends real frame time at the chosen bit rate, served in real time to an
// external client over SLCAN on TCP or a pty, or bridged to a SocketCAN interface, until SIGINT,
// SIGTERM or the duration. Fails when the link cannot be opened (kCommunication, the link's
// reason), a flash file cannot be opened (kIoError) or the firmware does not start.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

struct NodeOptions {
  enum class Link { kSlcanTcp, kSlcanPty, kSocketCan } link = Link::kSlcanTcp;
  uint16_t port = 0;     // kSlcanTcp (0: any free port, named in the first line and ready file)
  std::string pty_link;  // kSlcanPty: a symlink to the pty, or none
  std::string iface;     // kSocketCan
  uint32_t bitrate = 1000000;  // the bus's, and the board's factory default (bit/s)
  uint8_t node = 0x10;
  std::string flash_dir;  // flash files, written through, when not empty
  bool write_enable = false;
  double duration_s = 0;   // > 0: stop after this much wall time
  std::string ready_file;  // written with the client spec once the node serves
};

/// Serves until stopped; the start and stop lines go to `out`, warnings (stored settings
/// refused, a stored bit rate that takes the node off the bus) to `err`.
Outcome ServeNode(const NodeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace volcomp::sim
