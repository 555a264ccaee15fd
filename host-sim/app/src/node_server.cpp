// The simulated node process.
#include "volcomp/sim/node_server.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/can_io/transport.hpp"
#include "volcomp/sim/bus_bridge.hpp"
#include "volcomp/sim/realtime.hpp"
#include "volcomp/sim/simulated_board.hpp"

namespace volcomp::sim {
namespace {

std::atomic<bool> g_stop{false};
void OnSignal(int) { g_stop = true; }

struct NodeOptions {
  enum class Link { kSlcanTcp, kSlcanPty, kSocketCan } link = Link::kSlcanTcp;
  uint16_t port = 0;
  std::string pty_link;
  std::string iface;
  uint32_t bitrate = 1000000;
  uint8_t node = 0x10;
  std::string flash_dir;
  bool write_enable = false;
  double duration_s = 0;
  std::string ready_file;
};

NodeOptions Parse(const std::vector<std::string>& a) {
  NodeOptions o;
  auto value = [&](size_t& i) -> const std::string& {
    if (i + 1 >= a.size()) throw std::runtime_error("option " + a[i] + " needs a value");
    return a[++i];
  };
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] == "--slcan-tcp") {
      o.link = NodeOptions::Link::kSlcanTcp;
      o.port = static_cast<uint16_t>(std::stoul(value(i)));
    } else if (a[i] == "--slcan-pty") {
      o.link = NodeOptions::Link::kSlcanPty;
      if (i + 1 < a.size() && a[i + 1].rfind("--", 0) != 0) o.pty_link = a[++i];
    } else if (a[i] == "--socketcan") {
      o.link = NodeOptions::Link::kSocketCan;
      o.iface = value(i);
    } else if (a[i] == "--bitrate") {
      o.bitrate = static_cast<uint32_t>(std::stoul(value(i)));
      if (o.bitrate % 1000 != 0 || o.bitrate < 10000 || o.bitrate > 1000000) {
        throw std::runtime_error("--bitrate must be a whole kbit/s from 10000 to 1000000");
      }
    } else if (a[i] == "--node") {
      const unsigned long n = std::stoul(value(i));
      if (n < 1 || n > 127) throw std::runtime_error("--node must be 1..127");
      o.node = static_cast<uint8_t>(n);
    } else if (a[i] == "--flash-dir") {
      o.flash_dir = value(i);
    } else if (a[i] == "--write-enable") {
      o.write_enable = true;
    } else if (a[i] == "--duration") {
      o.duration_s = std::stod(value(i));
    } else if (a[i] == "--ready-file") {
      o.ready_file = value(i);
    } else {
      throw std::runtime_error("unknown option " + a[i]);
    }
  }
  return o;
}

}  // namespace

int RunNodeServer(const std::vector<std::string>& args) {
  const NodeOptions o = Parse(args);
  SimBus bus(o.bitrate);
  SimulatedBoardOptions bo;
  bo.settings.node_id = o.node;
  bo.settings.bitrate_kbit = static_cast<uint16_t>(o.bitrate / 1000);  // factory default
  bo.flash_dir = o.flash_dir;
  bo.write_enable_input = o.write_enable;
  SimulatedBoard board(bus, bo);
  Endpoint& ext = bus.Attach("external");

  std::unique_ptr<can_io::SlcanServer> server;
  std::unique_ptr<can_io::CanTransport> transport;
  std::string spec;
  // The can_io results as this command reports errors (it throws; main prints the message).
  const auto opened = [](auto result) {
    if (!result.ok()) throw std::runtime_error(result.error().message);
    if constexpr (!std::is_same_v<decltype(result), Outcome>) return std::move(result).value();
  };
  switch (o.link) {
    case NodeOptions::Link::kSlcanTcp:
      server = opened(can_io::SlcanServer::CreateTcp("127.0.0.1", o.port));
      spec = server->client_spec();
      break;
    case NodeOptions::Link::kSlcanPty: {
      can_io::SlcanServerOptions so;
      so.symlink = o.pty_link;
      server = opened(can_io::SlcanServer::CreatePty(so));
      spec = server->client_spec();
      break;
    }
    case NodeOptions::Link::kSocketCan:
      spec = "socketcan:" + o.iface;
      transport = opened(can_io::OpenTransport(spec));
      break;
  }
  if (!board.Start().ok()) throw std::runtime_error("the firmware did not start (configuration)");
  const Status config = board.app().config_status();
  if (!config.ok()) {
    std::fprintf(stderr,
                 "volcomp-sim node: the stored settings were refused (%s): running the "
                 "factory defaults\n",
                 ErrorText(config.error()));
  }
  const uint32_t board_bps = uint32_t{board.app().settings().bitrate_kbit} * 1000u;
  if (board_bps != o.bitrate) {
    std::fprintf(stderr,
                 "volcomp-sim node: warning: the board's stored bit rate is %u kbit/s, the bus "
                 "runs at %u kbit/s: the node is off the bus (restore with 0x1011 needs the "
                 "bus at %u kbit/s: --bitrate %u)\n",
                 board_bps / 1000u, o.bitrate / 1000u, board_bps / 1000u, board_bps);
  }
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  std::printf("volcomp-sim node %u on a simulated %.0f kbit/s bus, clients: %s\n", o.node,
              o.bitrate / 1000.0, spec.c_str());
  std::fflush(stdout);
  if (!o.ready_file.empty()) std::ofstream(o.ready_file) << spec << "\n";

  std::unique_ptr<SlcanBridge> bridge;
  if (server) bridge = std::make_unique<SlcanBridge>(bus, *server, ext);
  const RealtimeClock clock;
  const auto wall_start = std::chrono::steady_clock::now();
  while (!g_stop) {
    // Catch virtual time up with the wall clock, events in order.
    AdvanceInEventOrder(bus, board, clock.Now());
    // External I/O, waiting at most until the next event or 1 ms.
    auto wait = clock.Until(NextEventTime(bus, board));
    if (wait > std::chrono::microseconds(1000)) wait = std::chrono::microseconds(1000);
    if (server) {
      opened(bridge->Serve(wait));
    } else {
      CanFrame f;
      while (ext.Receive(&f)) opened(transport->Send(f));
      if (auto f2 = opened(transport->Receive(wait))) ext.Send(*f2);
      opened(PumpTransport(*transport, ext));
    }
    if (o.duration_s > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count() >=
            o.duration_s) {
      break;
    }
  }
  board.SaveFlash();
  std::printf("volcomp-sim node: stopped after %.1f s of simulated time\n",
              static_cast<double>(clock.Now()) * 1e-9);
  return 0;
}

}  // namespace volcomp::sim
