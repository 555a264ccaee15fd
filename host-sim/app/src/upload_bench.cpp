// Upload throughput over the simulated bus.
#include "volcomp/sim/upload_bench.hpp"

#include <cmath>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/crc16.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_protocol.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/sim/sim_sdo_host.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::sim {
namespace {

using canopen::ObjectId;
using canopen::TableCommand;
namespace sdo = canopen::sdo;

Expected<std::vector<uint8_t>> BuildGridImage(uint32_t n) {
  std::vector<int16_t> values(size_t{n} * n * n * 3);
  for (uint32_t k = 0; k < n; ++k) {
    for (uint32_t j = 0; j < n; ++j) {
      for (uint32_t i = 0; i < n; ++i) {
        const size_t node = (size_t{k} * n + j) * n + i;
        values[node * 3 + 0] = static_cast<int16_t>(400 * std::sin(0.2 * i) + 30 * j);
        values[node * 3 + 1] = static_cast<int16_t>(-250 + 15 * i - 20 * k);
        values[node * 3 + 2] = static_cast<int16_t>(100 * std::cos(0.15 * (i + j)) + 5 * k);
      }
    }
  }
  table::GridSpec g;
  g.frac_bits = 4;
  for (auto& d : g.dim) d = {n, 0, 15625};
  g.values.i16 = values.data();
  table::ImageSpec s;
  s.table_id = 33;
  s.axis_count = 3;
  s.axes[0] = {'X', table::AxisKind::kLinear, 1000000};
  s.axes[1] = {'Y', table::AxisKind::kLinear, 1000000};
  s.axes[2] = {'Z', table::AxisKind::kLinear, 1000000};
  s.grid = &g;
  const Result<uint32_t> bytes = table::ImageSize(s);
  if (!bytes.ok()) return Fail(bytes.status(), "the benchmark's grid image");
  std::vector<uint32_t> words((*bytes + 3) / 4);
  uint8_t* out = reinterpret_cast<uint8_t*>(words.data());
  const Result<uint32_t> size = table::WriteImage(s, out, words.size() * 4);
  if (!size.ok()) return Fail(size.status(), "the benchmark's grid image");
  return std::vector<uint8_t>(out, out + *size);
}

}  // namespace

double NoStuffingCeilingBytesPerS(uint32_t bitrate) {
  constexpr double kFrameBits = 111, kSegmentBytes = 7, kSegmentsPerAck = 127;
  return bitrate * kSegmentBytes * kSegmentsPerAck / (kFrameBits * (kSegmentsPerAck + 1));
}

uint64_t IdealBlockDownloadBits(const std::vector<uint8_t>& payload, uint8_t node_id) {
  const uint32_t rx = sdo::kRequestCobBase + node_id, tx = sdo::kResponseCobBase + node_id;
  auto frame = [](uint32_t id, std::initializer_list<uint8_t> bytes) {
    CanFrame f;
    f.id = id;
    f.dlc = 8;
    int i = 0;
    for (uint8_t b : bytes) f.data[i++] = b;
    return f;
  };
  const uint16_t index = canopen::Entry(ObjectId::kTableData).index;
  const uint8_t lo = static_cast<uint8_t>(index), hi = static_cast<uint8_t>(index >> 8);
  constexpr uint8_t kBlock = sdo::kMaxBlockSize;
  constexpr uint32_t kSeg = sdo::kSegmentBytes;
  const uint32_t size = static_cast<uint32_t>(payload.size());
  uint64_t bits = CanFrameBits(
      frame(rx, {sdo::Block(sdo::kCcsBlockDownload, sdo::kBlockInitiate, true, true), lo, hi, 0,
                 uint8_t(size), uint8_t(size >> 8), uint8_t(size >> 16), uint8_t(size >> 24)}));
  bits += CanFrameBits(frame(
      tx, {sdo::Block(sdo::kScsBlockDownload, sdo::kBlockInitiate, true), lo, hi, 0, kBlock}));
  const uint32_t segments = (size + kSeg - 1) / kSeg;
  for (uint32_t s = 0; s < segments; ++s) {
    CanFrame f;
    f.id = rx;
    f.dlc = 8;
    const uint8_t seq = static_cast<uint8_t>(s % kBlock + 1);
    f.data[0] = sdo::BlockSegment(seq, s + 1 == segments);
    for (uint32_t i = 0; i < kSeg && s * kSeg + i < size; ++i)
      f.data[1 + i] = payload[s * kSeg + i];
    bits += CanFrameBits(f);
    if (seq == kBlock || s + 1 == segments) {
      bits += CanFrameBits(
          frame(tx, {sdo::Block(sdo::kScsBlockDownload, sdo::kBlockAck), seq, kBlock}));
    }
  }
  const uint16_t crc = canopen::Crc16Update(0, payload.data(), payload.size());
  const uint32_t unused = (kSeg - size % kSeg) % kSeg;
  bits += CanFrameBits(frame(
      rx, {sdo::BlockEndCommand(sdo::kCcsBlockDownload, unused), uint8_t(crc), uint8_t(crc >> 8)}));
  bits += CanFrameBits(frame(tx, {sdo::Block(sdo::kScsBlockDownload, sdo::kBlockEnd)}));
  return bits;
}

Expected<UploadBenchResult> RunUploadBench(const UploadBenchOptions& options) {
  if (options.bitrate == 0) return Fail(Error::kInvalidArgument, "the bit rate must be > 0");
  UploadBenchResult r;
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> image, BuildGridImage(options.grid_nodes));
  r.image_bytes = static_cast<uint32_t>(image.size());
  r.image_crc = LoadLe32(image.data() + image.size() - 4);
  SimBus bus(options.bitrate);
  SimulatedBoardOptions bo;
  bo.poll_period_ns = options.poll_period_ns;
  SimulatedBoard board(bus, bo);
  Endpoint& pc = bus.Attach("pc");
  VOLCOMP_TRY(board.Start());
  const uint8_t node = bo.settings.node_id;
  SimSdoHost host(bus, board, pc, node);
  host.Idle(5000000);
  // The PC tool's staging steps around the timed transfer, which runs event by event.
  canopen_client::NodeObjects pc_tool(host.Link(), node);
  auto fail = [](const std::string& what, const canopen_client::SdoFailure& failure) {
    return Fail(failure.code, what + ": " + failure.message);
  };
  const auto prepared = canopen_client::PrepareStaging(pc_tool);
  if (!prepared.ok()) return fail("staging", prepared.error());

  uint64_t frames_before = bus.stats().frames;
  const canopen::ObjectEntry& data = canopen::Entry(ObjectId::kTableData);
  canopen_client::SdoClient c(node);
  c.StartWrite(data.index, data.sub, image);
  const uint64_t t0 = bus.now();
  host.Run(c, 60000000000ull);
  if (!c.result().ok()) return fail("block download", c.result().error());
  const double bytes = static_cast<double>(image.size());
  r.transfer_s = static_cast<double>(bus.now() - t0) * 1e-9;
  r.frames = bus.stats().frames - frames_before;
  r.resent_segments = c.resent_segments();
  r.limit_s = static_cast<double>(IdealBlockDownloadBits(image, node)) / options.bitrate;
  r.rate_bytes_s = bytes / r.transfer_s;
  r.limit_bytes_s = bytes / r.limit_s;
  r.efficiency = r.limit_s / r.transfer_s;
  r.ceiling_bytes_s = NoStuffingCeilingBytesPerS(options.bitrate);
  r.ceiling_share = r.rate_bytes_s / r.ceiling_bytes_s;

  const auto verified = canopen_client::VerifyStaged(pc_tool, r.image_crc);
  if (!verified.ok()) return fail("verify", verified.error());
  if (options.activate) {
    const auto referenced = pc_tool.Write(ObjectId::kReferenceAxes, 0x07);
    if (!referenced.ok()) return fail("reference", referenced.error());
    host.Idle(200000000);
    const auto activated = canopen_client::WriteTableCommand(pc_tool, TableCommand::kActivate);
    if (!activated.ok()) return fail("activate", activated.error());
    r.activated = true;
  }
  const auto active = pc_tool.Read(ObjectId::kActiveTableCrc);
  if (!active.ok()) return fail("read active CRC", active.error());
  r.active_crc = *active;
  return r;
}

}  // namespace volcomp::sim
