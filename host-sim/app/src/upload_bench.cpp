// Upload throughput over the simulated bus.
#include "volcomp/sim/upload_bench.hpp"

#include <cmath>

#include "volcomp/byte_order.hpp"
#include "volcomp/canopen/crc16.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/sim/sim_sdo_host.hpp"
#include "volcomp/table_writer.hpp"

namespace volcomp::sim {
namespace {

std::vector<uint8_t> BuildGridImage(uint32_t n) {
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
  std::vector<uint32_t> words((*table::ImageSize(s) + 3) / 4);
  uint8_t* out = reinterpret_cast<uint8_t*>(words.data());
  const Result<uint32_t> size = table::WriteImage(s, out, words.size() * 4);
  return std::vector<uint8_t>(out, out + (size.ok() ? *size : 0));
}

}  // namespace

uint64_t IdealBlockDownloadBits(const std::vector<uint8_t>& payload, uint8_t node_id) {
  const uint32_t rx = 0x600u + node_id, tx = 0x580u + node_id;
  auto frame = [](uint32_t id, std::initializer_list<uint8_t> bytes) {
    CanFrame f;
    f.id = id;
    f.dlc = 8;
    int i = 0;
    for (uint8_t b : bytes) f.data[i++] = b;
    return f;
  };
  const uint32_t size = static_cast<uint32_t>(payload.size());
  uint64_t bits = CanFrameBits(frame(rx, {0xC6, 0x00, 0x21, 0x00, uint8_t(size), uint8_t(size >> 8),
                                          uint8_t(size >> 16), uint8_t(size >> 24)}));
  bits += CanFrameBits(frame(tx, {0xA4, 0x00, 0x21, 0x00, 127}));
  const uint32_t segments = (size + 6) / 7;
  for (uint32_t s = 0; s < segments; ++s) {
    CanFrame f;
    f.id = rx;
    f.dlc = 8;
    const uint32_t seq = s % 127 + 1;
    f.data[0] = static_cast<uint8_t>(seq | (s + 1 == segments ? 0x80 : 0));
    for (uint32_t i = 0; i < 7 && s * 7 + i < size; ++i) f.data[1 + i] = payload[s * 7 + i];
    bits += CanFrameBits(f);
    if (seq == 127 || s + 1 == segments) bits += CanFrameBits(frame(tx, {0xA2, uint8_t(seq), 127}));
  }
  const uint16_t crc = canopen::Crc16Update(0, payload.data(), payload.size());
  bits += CanFrameBits(frame(rx, {0xC1, uint8_t(crc), uint8_t(crc >> 8)}));
  bits += CanFrameBits(frame(tx, {0xA1}));
  return bits;
}

UploadBenchResult RunUploadBench(const UploadBenchOptions& options) {
  UploadBenchResult r;
  const std::vector<uint8_t> image = BuildGridImage(options.grid_nodes);
  r.image_bytes = static_cast<uint32_t>(image.size());
  r.image_crc = LoadLe32(image.data() + image.size() - 4);
  SimBus bus(options.bitrate);
  SimulatedBoardOptions bo;
  bo.poll_period_ns = options.poll_period_ns;
  SimulatedBoard board(bus, bo);
  Endpoint& pc = bus.Attach("pc");
  if (!board.Start().ok()) {
    r.message = "the simulated board did not start";
    return r;
  }
  const uint8_t node = bo.settings.node_id;
  SimSdoHost host(bus, board, pc, node);
  host.Idle(5000000);
  constexpr uint64_t kWriteTimeoutNs = 2000000000ull;
  auto write = [&](canopen::ObjectId id, uint32_t v) { return host.Write(id, v, kWriteTimeoutNs); };
  auto fail = [&](const std::string& what, const canopen_client::SdoResult& res) {
    r.message = what + ": " + res.message;
    return r;
  };
  auto res = write(canopen::ObjectId::kUnlock, canopen::kUnlockSignature);
  if (!res.ok) return fail("unlock", res);
  res = write(canopen::ObjectId::kTableControl, 3);
  if (!res.ok) return fail("clear", res);

  uint64_t frames_before = bus.stats().frames;
  const canopen::ObjectEntry& data = canopen::Entry(canopen::ObjectId::kTableData);
  canopen_client::SdoClient c(node);
  c.StartDownload(data.index, data.sub, image);
  const uint64_t t0 = bus.now();
  host.Run(c, 60000000000ull);
  if (!c.done() || !c.result().ok) return fail("block download", c.result());
  const double bytes = static_cast<double>(image.size());
  r.transfer_s = static_cast<double>(bus.now() - t0) * 1e-9;
  r.frames = bus.stats().frames - frames_before;
  r.resent_segments = c.resent_segments();
  r.limit_s = static_cast<double>(IdealBlockDownloadBits(image, node)) / options.bitrate;
  r.rate_bytes_s = bytes / r.transfer_s;
  r.limit_bytes_s = bytes / r.limit_s;
  r.efficiency = r.limit_s / r.transfer_s;

  res = write(canopen::ObjectId::kTableControl, 4);
  if (!res.ok) return fail("verify", res);
  if (options.activate) {
    res = write(canopen::ObjectId::kReferenceAxes, 0x07);
    if (!res.ok) return fail("reference", res);
    host.Idle(200000000);
    res = write(canopen::ObjectId::kTableControl, 1);
    if (!res.ok) return fail("activate", res);
    r.activated = true;
  }
  const canopen::ObjectEntry& active = canopen::Entry(canopen::ObjectId::kActiveTableCrc);
  canopen_client::SdoClient rd(node);
  rd.StartUpload(active.index, active.sub);
  host.Run(rd, kWriteTimeoutNs);
  if (!rd.result().ok || rd.result().data.size() != 4) return fail("read active CRC", rd.result());
  r.active_crc = LoadLe32(rd.result().data.data());
  r.ok = true;
  r.message = "ok";
  return r;
}

}  // namespace volcomp::sim
