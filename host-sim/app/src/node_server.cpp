// The simulated node process.
#include "volcomp/sim/node_server.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>

#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/can_io/transport.hpp"
#include "volcomp/sim/bus_bridge.hpp"
#include "volcomp/sim/realtime.hpp"
#include "volcomp/sim/simulated_board.hpp"

namespace volcomp::sim {
namespace {

std::atomic<bool> g_stop{false};
void OnSignal(int) { g_stop = true; }

// The external link: an SLCAN server, or a transport to a SocketCAN interface.
struct Link {
  std::unique_ptr<can_io::SlcanServer> server;
  std::unique_ptr<can_io::CanTransport> transport;
  std::string spec;
};

Expected<Link> OpenLink(const NodeOptions& o) {
  Link link;
  switch (o.link) {
    case NodeOptions::Link::kSlcanTcp: {
      VOLCOMP_TRY_ASSIGN(link.server, can_io::SlcanServer::CreateTcp("127.0.0.1", o.port));
      link.spec = link.server->client_spec();
      break;
    }
    case NodeOptions::Link::kSlcanPty: {
      can_io::SlcanServerOptions so;
      so.symlink = o.pty_link;
      VOLCOMP_TRY_ASSIGN(link.server, can_io::SlcanServer::CreatePty(so));
      link.spec = link.server->client_spec();
      break;
    }
    case NodeOptions::Link::kSocketCan: {
      link.spec = "socketcan:" + o.iface;
      VOLCOMP_TRY_ASSIGN(link.transport, can_io::OpenTransport(link.spec));
      break;
    }
  }
  return link;
}

// One exchange with a SocketCAN transport: what the node sent out, then up to `wait` for a frame.
Outcome ServeTransport(can_io::CanTransport& transport,
                       Endpoint& ext,
                       std::chrono::microseconds wait) {
  CanFrame f;
  while (ext.Receive(&f)) VOLCOMP_TRY(transport.Send(f));
  VOLCOMP_TRY_ASSIGN(const std::optional<CanFrame> received, transport.Receive(wait));
  if (received) ext.Send(*received);
  VOLCOMP_TRY(PumpTransport(transport, ext));
  return Outcome::Ok();
}

// `value` with `decimals` digits after the point.
std::string Fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

Outcome ServeNode(const NodeOptions& o, std::ostream& out, std::ostream& err) {
  SimBus bus(o.bitrate);
  SimulatedBoardOptions bo;
  bo.settings.node_id = o.node;
  bo.settings.bitrate_kbit = static_cast<uint16_t>(o.bitrate / 1000);  // factory default
  bo.flash_dir = o.flash_dir;
  bo.write_enable_input = o.write_enable;
  SimulatedBoard board(bus, bo);
  Endpoint& ext = bus.Attach("external");
  VOLCOMP_TRY_ASSIGN(Link link, OpenLink(o));
  VOLCOMP_TRY(board.Start());
  const Status config = board.app().config_status();
  if (!config.ok()) {
    err << "volcomp-sim node: the stored settings were refused (" << ErrorText(config.error())
        << "): running the factory defaults\n";
  }
  const uint32_t board_bps = uint32_t{board.app().settings().bitrate_kbit} * 1000u;
  if (board_bps != o.bitrate) {
    err << "volcomp-sim node: warning: the board's stored bit rate is " << board_bps / 1000u
        << " kbit/s, the bus runs at " << o.bitrate / 1000u
        << " kbit/s: the node is off the bus (restore with 0x1011 needs the bus at "
        << board_bps / 1000u << " kbit/s: --bitrate " << board_bps << ")\n";
  }
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  out << "volcomp-sim node " << unsigned{o.node} << " on a simulated "
      << Fixed(o.bitrate / 1000.0, 0) << " kbit/s bus, clients: " << link.spec << "\n"
      << std::flush;
  if (!o.ready_file.empty()) std::ofstream(o.ready_file) << link.spec << "\n";

  std::unique_ptr<SlcanBridge> bridge;
  if (link.server) bridge = std::make_unique<SlcanBridge>(bus, *link.server, ext);
  const RealtimeClock clock;
  const auto wall_start = std::chrono::steady_clock::now();
  while (!g_stop) {
    // Catch virtual time up with the wall clock, events in order.
    AdvanceInEventOrder(bus, board, clock.Now());
    // External I/O, waiting at most until the next event or 1 ms.
    auto wait = clock.Until(NextEventTime(bus, board));
    if (wait > std::chrono::microseconds(1000)) wait = std::chrono::microseconds(1000);
    if (bridge) {
      VOLCOMP_TRY(bridge->Serve(wait));
    } else {
      VOLCOMP_TRY(ServeTransport(*link.transport, ext, wait));
    }
    if (o.duration_s > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count() >=
            o.duration_s) {
      break;
    }
  }
  board.SaveFlash();
  out << "volcomp-sim node: stopped after " << Fixed(static_cast<double>(clock.Now()) * 1e-9, 1)
      << " s of simulated time\n";
  return Outcome::Ok();
}

}  // namespace volcomp::sim
