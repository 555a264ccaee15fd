// `volcomp-sim`: the host simulator. Subcommands:
//   node          the real firmware on the mock HAL on a simulated bus, served to external CAN
//                 clients over SLCAN (pty or TCP) or a SocketCAN interface, in real time
//   bench-upload  upload throughput of a 33x33x33 int16 grid over the simulated 1 Mbit/s bus
//   demo          the main job: measure -> evaluate -> build -> upload -> re-measure (virtual time)
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "volcomp/sim/node_server.hpp"
#ifdef VOLCOMP_SIM_HAS_DEMO
#include "volcomp/sim/demo_cli.hpp"
#endif
#include "volcomp/sim/upload_bench.hpp"

namespace {

int BenchUpload(const std::vector<std::string>& args) {
  volcomp::sim::UploadBenchOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--bitrate" && i + 1 < args.size()) {
      o.bitrate = static_cast<uint32_t>(std::stoul(args[++i]));
    } else if (args[i] == "--nodes" && i + 1 < args.size()) {
      o.grid_nodes = static_cast<uint32_t>(std::stoul(args[++i]));
    } else {
      std::fprintf(stderr, "volcomp-sim bench-upload: unknown option %s\n", args[i].c_str());
      return 2;
    }
  }
  const volcomp::sim::UploadBenchResult r = volcomp::sim::RunUploadBench(o);
  if (!r.ok) {
    std::fprintf(stderr, "volcomp-sim bench-upload: %s\n", r.message.c_str());
    return 1;
  }
  std::printf("upload of a %ux%ux%u int16 grid (%u bytes) over the simulated %.0f kbit/s bus:\n",
              o.grid_nodes, o.grid_nodes, o.grid_nodes, r.image_bytes, o.bitrate / 1000.0);
  std::printf("  block download  %.3f s   %.1f kB/s   %llu frames, %u segments resent\n",
              r.transfer_s, r.rate_bytes_s / 1000, static_cast<unsigned long long>(r.frames),
              r.resent_segments);
  std::printf("  SDO-block limit %.3f s   %.1f kB/s   (same payload, no turnaround)\n", r.limit_s,
              r.limit_bytes_s / 1000);
  std::printf("  efficiency      %.1f %% of the limit\n", 100 * r.efficiency);
  std::printf(
      "  bus ceiling     %.1f kB/s   (8-byte frames, no stuff bits, 1 ack per 127 "
      "segments): %.1f %% of it\n",
      r.ceiling_bytes_s / 1000, 100 * r.ceiling_share);
  std::printf("  activated: %s, active CRC-32 0x%08X (image 0x%08X)\n", r.activated ? "yes" : "no",
              r.active_crc, r.image_crc);
  return r.active_crc == r.image_crc ? 0 : 1;
}

void Usage() {
  std::printf(
      "usage: volcomp-sim COMMAND [options]\n\n"
      "  node [--slcan-tcp PORT | --slcan-pty [LINK] | --socketcan IFACE] [--bitrate N]\n"
      "       [--node ID] [--flash-dir DIR] [--write-enable] [--duration S]\n"
      "       the real firmware on the mock HAL, on a simulated bus, served in real time\n"
      "  bench-upload [--bitrate N] [--nodes N]\n"
      "       upload throughput over the simulated bus (virtual time)\n");
#ifdef VOLCOMP_SIM_HAS_DEMO
  std::printf("%s", volcomp::sim::DemoUsage());
#endif
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "help") {
    Usage();
    return args.empty() ? 2 : 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  try {
    if (cmd == "bench-upload") return BenchUpload(args);
    if (cmd == "node") return volcomp::sim::RunNodeServer(args);
#ifdef VOLCOMP_SIM_HAS_DEMO
    if (cmd == "demo") return volcomp::sim::RunDemoCommand(args);
#endif
  } catch (const std::exception& e) {
    std::fprintf(stderr, "volcomp-sim %s: %s\n", cmd.c_str(), e.what());
    return 1;
  }
  std::fprintf(stderr, "volcomp-sim: unknown command \"%s\"\n", cmd.c_str());
  Usage();
  return 2;
}
