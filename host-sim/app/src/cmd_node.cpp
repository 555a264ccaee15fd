// `volcomp-sim node`: the real firmware on the mock HAL on a simulated bus, served in real time.
#include "commands.hpp"
#include "volcomp/sim/node_server.hpp"

namespace volcomp::sim {
namespace {

Expected<int> RunNode(args::Args& args, Context& ctx) {
  const auto port = args.Integer("--slcan-tcp");
  const auto iface = args.Value("--socketcan");
  const auto bitrate = args.Integer("--bitrate");
  const auto node = args.Integer("--node");
  NodeOptions o;
  o.flash_dir = args.Value("--flash-dir").value_or("");
  o.write_enable = args.Flag("--write-enable");
  o.duration_s = args.Number("--duration").value_or(0);
  o.ready_file = args.Value("--ready-file").value_or("");  // for scripts: the client spec
  // `--slcan-pty [LINK]`: the link is the word left once every other option took its own.
  const bool pty = args.Flag("--slcan-pty");
  const std::vector<std::string> rest = pty ? args.Positionals() : std::vector<std::string>{};
  VOLCOMP_TRY(args.Finish());
  if (rest.size() > 1) return UsageFailure("unexpected argument \"" + rest[1] + "\"");
  if (int{port.has_value()} + int{iface.has_value()} + int{pty} > 1) {
    return UsageFailure("give one of --slcan-tcp, --slcan-pty, --socketcan");
  }
  if (port) {
    if (*port < 0 || *port > 65535) return UsageFailure("--slcan-tcp must be a port 0..65535");
    o.link = NodeOptions::Link::kSlcanTcp;
    o.port = static_cast<uint16_t>(*port);
  } else if (iface) {
    o.link = NodeOptions::Link::kSocketCan;
    o.iface = *iface;
  } else if (pty) {
    o.link = NodeOptions::Link::kSlcanPty;
    if (!rest.empty()) o.pty_link = rest[0];
  }
  if (bitrate) {
    if (*bitrate % 1000 != 0 || *bitrate < 10000 || *bitrate > 1000000) {
      return UsageFailure("--bitrate must be a whole kbit/s from 10000 to 1000000");
    }
    o.bitrate = static_cast<uint32_t>(*bitrate);
  }
  if (node) {
    if (*node < 1 || *node > 127) return UsageFailure("--node must be 1..127");
    o.node = static_cast<uint8_t>(*node);
  }
  VOLCOMP_TRY(ServeNode(o, ctx.out, ctx.err));
  return 0;
}

}  // namespace

const Command& NodeCommand() {
  static const Command command{
      "node",
      "  node [--slcan-tcp PORT | --slcan-pty [LINK] | --socketcan IFACE] [--bitrate N]\n"
      "       [--node ID] [--flash-dir DIR] [--write-enable] [--duration S]\n"
      "       the real firmware on the mock HAL, on a simulated bus, served in real time\n",
      RunNode};
  return command;
}

}  // namespace volcomp::sim
