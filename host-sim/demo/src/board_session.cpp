// Table transfer to the simulated board with the PC tool's protocol code.
#include "volcomp/sim/board_session.hpp"

#include <cstdio>
#include <string>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::sim {

using canopen::ObjectId;
using canopen_client::Explain;
using canopen_client::NodeObjects;
using canopen_client::SdoFailure;

namespace {

Unexpected<Failure> Failed(const SdoFailure& failure) {
  return Fail(Error::kIoError, failure.message);
}

}  // namespace

Expected<UploadReport> UploadTable(World& world,
                                   const std::vector<uint8_t>& image,
                                   std::ostream& log) {
  UploadReport r;
  r.bytes = static_cast<uint32_t>(image.size());
  r.image_crc = LoadLe32(image.data() + image.size() - 4);
  NodeObjects node(world.SdoLink(), world.node_id());
  const auto active =
      Explain(node.Read(ObjectId::kActiveTableCrc), "reading the active CRC-32 (0x2104)");
  if (!active.ok()) return Failed(active.error());
  const auto bank_size =
      Explain(node.Read(ObjectId::kTableBankSize), "reading the bank size (0x2108)");
  if (!bank_size.ok()) return Failed(bank_size.error());
  const uint32_t bank = *bank_size;
  if (image.size() > bank) {
    return Fail(Error::kImageTooLarge, "the image (" + std::to_string(image.size()) +
                                           " bytes) does not fit the board's table bank (" +
                                           std::to_string(bank) + " bytes)");
  }
  const auto prepared = canopen_client::PrepareStaging(node);
  if (!prepared.ok()) return Failed(prepared.error());

  const uint64_t frames0 = world.bus().stats().frames;
  const uint64_t t0 = world.now_ns();
  int decile = -1;
  const canopen::ObjectEntry& data = canopen::Entry(ObjectId::kTableData);
  canopen_client::SdoClient client(world.node_id());
  client.StartWrite(data.index, data.sub, image, [&](uint32_t done, uint32_t total) {
    const int d = total ? static_cast<int>(10ull * done / total) : 10;
    if (d > decile) {
      decile = d;
      const double s = static_cast<double>(world.now_ns() - t0) * 1e-9;
      char line[128];
      std::snprintf(line, sizeof line, "      %3d%%  %u/%u bytes  %.2f s virtual\n", d * 10, done,
                    total, s);
      log << line << std::flush;
    }
  });
  const auto written = Explain(canopen_client::RunToCompletion(client, world.SdoLink()),
                               "block download into 0x2100");
  if (!written.ok()) return Failed(written.error());
  r.transfer_s = static_cast<double>(world.now_ns() - t0) * 1e-9;
  r.rate_bytes_s = r.transfer_s > 0 ? r.bytes / r.transfer_s : 0;
  r.frames = world.bus().stats().frames - frames0;
  r.resent_segments = client.resent_segments();

  const auto verified = canopen_client::VerifyStaged(node, r.image_crc);
  if (!verified.ok()) return Failed(verified.error());
  r.staged_crc = r.image_crc;  // verified: the board staged exactly the image
  return r;
}

Expected<ActivationReport> ActivateTable(World& world, uint32_t expected_crc) {
  ActivationReport r;
  NodeObjects node(world.SdoLink(), world.node_id());
  const auto activated = canopen_client::WriteTableCommand(node, canopen::TableCommand::kActivate);
  if (!activated.ok()) return Failed(activated.error());
  const auto active =
      Explain(node.Read(ObjectId::kActiveTableCrc), "reading the active CRC-32 (0x2104)");
  if (!active.ok()) return Failed(active.error());
  r.active_crc = *active;
  if (r.active_crc != expected_crc) {
    return Fail(Error::kImageBadCrc, "the active CRC-32 is " + tools::Hex32(r.active_crc) +
                                         ", the uploaded image's " + tools::Hex32(expected_crc));
  }
  r.device_state = ReadDeviceState(world);
  return r;
}

uint16_t ReadDeviceState(World& world) {
  const auto v = NodeObjects(world.SdoLink(), world.node_id()).Read(ObjectId::kDeviceState);
  return v.ok() ? static_cast<uint16_t>(*v) : 0;
}

}  // namespace volcomp::sim
