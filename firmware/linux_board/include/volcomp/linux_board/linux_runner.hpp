// volcomp-fw-linux's process: opens the devices named by the configuration (SocketCAN ports,
// flash files, GPIO backend), starts GatewayApp and runs one event loop (epoll) over
//
//   the controller socket   every frame: forwarded to the drives (corrected), NMT and the board's
//                           own SDO requests also to the node (answered at once);
//   the drive socket        every frame: forwarded to the controller (corrected);
//   a timerfd at tick_hz    the control tick (missed periods are caught up, at most 10 at once,
//                           and counted), slow lines every poll_ms, the node's main-loop pass,
//                           flushing of paced CAN queues;
//   a signalfd              SIGINT / SIGTERM / SIGHUP: clean shutdown (outputs inactive, CAN
//                           queues flushed, statistics written).
//
// Per-frame forwarding latency: for each forwarded frame, from the kernel's receive timestamp
// (SIOCGSTAMPNS on the receiving socket, CLOCK_REALTIME) to the return of the write() that
// queued the corrected frame on the other interface; and the in-process part alone (read()
// returned -> write() returned, CLOCK_MONOTONIC). Both per direction, in the exit report and the
// --stats file.
//
// Single-threaded; nothing runs in signal context.
#pragma once

#include <string>

#include "volcomp/linux_board/config_file.hpp"

namespace volcomp::linux_board {

struct RunOptions {
  std::string ready_file;  // written once the board is running (tests wait for it)
  std::string stats_file;  // JSON statistics written at exit
  double duration_s = 0;   // stop after this long (0 = until a signal)
  bool measure_latency = true;
};

/// Runs the board until a signal (or the duration). Returns the process exit code; errors are
/// reported on stderr.
int RunLinuxBoard(const LinuxBoardConfig& config, const RunOptions& options);

}  // namespace volcomp::linux_board
