// `volcomp-sim bench-upload`: upload throughput over the simulated bus (virtual time).
#include <cstdint>
#include <cstdio>

#include "commands.hpp"
#include "volcomp/sim/upload_bench.hpp"

namespace volcomp::sim {
namespace {

Expected<int> RunBenchUpload(args::Args& args, Context& ctx) {
  const auto bitrate = args.Integer("--bitrate");
  const auto nodes = args.Integer("--nodes");
  VOLCOMP_TRY(args.Finish());
  UploadBenchOptions o;
  if (bitrate) {
    if (*bitrate < 1 || *bitrate > UINT32_MAX) return UsageFailure("--bitrate must be > 0 bit/s");
    o.bitrate = static_cast<uint32_t>(*bitrate);
  }
  if (nodes) {
    // The GRID3 format's range; the board's bank holds far fewer (the upload then fails).
    if (*nodes < 2 || *nodes > 1024) return UsageFailure("--nodes must be 2..1024");
    o.grid_nodes = static_cast<uint32_t>(*nodes);
  }
  VOLCOMP_TRY_ASSIGN(const UploadBenchResult r, RunUploadBench(o));
  char b[512];
  std::snprintf(b, sizeof b,
                "upload of a %ux%ux%u int16 grid (%u bytes) over the simulated %.0f kbit/s bus:\n",
                o.grid_nodes, o.grid_nodes, o.grid_nodes, r.image_bytes, o.bitrate / 1000.0);
  ctx.out << b;
  std::snprintf(b, sizeof b,
                "  block download  %.3f s   %.1f kB/s   %llu frames, %u segments resent\n",
                r.transfer_s, r.rate_bytes_s / 1000, static_cast<unsigned long long>(r.frames),
                r.resent_segments);
  ctx.out << b;
  std::snprintf(b, sizeof b,
                "  SDO-block limit %.3f s   %.1f kB/s   (same payload, no turnaround)\n", r.limit_s,
                r.limit_bytes_s / 1000);
  ctx.out << b;
  std::snprintf(b, sizeof b, "  efficiency      %.1f %% of the limit\n", 100 * r.efficiency);
  ctx.out << b;
  std::snprintf(b, sizeof b,
                "  bus ceiling     %.1f kB/s   (8-byte frames, no stuff bits, 1 ack per 127 "
                "segments): %.1f %% of it\n",
                r.ceiling_bytes_s / 1000, 100 * r.ceiling_share);
  ctx.out << b;
  std::snprintf(b, sizeof b, "  activated: %s, active CRC-32 0x%08X (image 0x%08X)\n",
                r.activated ? "yes" : "no", r.active_crc, r.image_crc);
  ctx.out << b;
  return r.active_crc == r.image_crc ? 0 : 1;
}

}  // namespace

const Command& BenchUploadCommand() {
  static const Command command{"bench-upload",
                               "  bench-upload [--bitrate N] [--nodes N]\n"
                               "       upload throughput over the simulated bus (virtual time)\n",
                               RunBenchUpload};
  return command;
}

}  // namespace volcomp::sim
