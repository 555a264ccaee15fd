// Table transfer to the simulated board with the PC tool's protocol code.
#include "volcomp/sim/board_session.hpp"

#include <cstdio>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/sdo_runner.hpp"

namespace volcomp::sim {
namespace {

using canopen::ObjectId;
using canopen_client::SdoResult;

constexpr uint32_t kUnlockSignature = 0x6B6C6E75;  // "unlk"

SdoResult Write(World& w, ObjectId id, uint32_t value) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return canopen_client::WriteU32(w.SdoLink(), w.node_id(), e.index, e.sub, value,
                                  static_cast<uint8_t>(canopen::FixedSize(e.type)));
}

SdoResult Read(World& w, ObjectId id, uint32_t* value) {
  const canopen::ObjectEntry& e = canopen::Entry(id);
  return canopen_client::ReadU32(w.SdoLink(), w.node_id(), e.index, e.sub, value);
}

std::string Hex32(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

}  // namespace

UploadReport UploadTable(World& world, const std::vector<uint8_t>& image, std::ostream& log) {
  UploadReport r;
  r.bytes = static_cast<uint32_t>(image.size());
  r.image_crc = static_cast<uint32_t>(image[image.size() - 4]) |
                static_cast<uint32_t>(image[image.size() - 3]) << 8 |
                static_cast<uint32_t>(image[image.size() - 2]) << 16 |
                static_cast<uint32_t>(image[image.size() - 1]) << 24;
  auto fail = [&](const std::string& what, const SdoResult& res) {
    r.message = what + ": " + res.message;
    return r;
  };
  uint32_t active = 0, bank = 0, writable = 0;
  SdoResult res = Read(world, ObjectId::kActiveTableCrc, &active);
  if (!res.ok) return fail("reading the active CRC-32 (0x2104)", res);
  res = Read(world, ObjectId::kTableBankSize, &bank);
  if (!res.ok) return fail("reading the bank size (0x2108)", res);
  if (image.size() > bank) {
    r.message = "the image does not fit the board's table bank";
    return r;
  }
  res = Read(world, ObjectId::kWriteAccess, &writable);
  if (!res.ok) return fail("reading write access (0x2111)", res);
  if (writable == 0) {
    res = Write(world, ObjectId::kUnlock, kUnlockSignature);
    if (!res.ok) return fail("unlocking (0x2110)", res);
  }
  res = Write(world, ObjectId::kTableControl, 3);
  if (!res.ok) return fail("clearing the staging bank (0x2101 = 3)", res);

  const uint64_t frames0 = world.bus().stats().frames;
  const uint64_t t0 = world.now_ns();
  int decile = -1;
  const canopen::ObjectEntry& data = canopen::Entry(ObjectId::kTableData);
  canopen_client::SdoClient client(world.node_id());
  client.StartDownload(data.index, data.sub, image, [&](uint32_t done, uint32_t total) {
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
  res = canopen_client::RunToCompletion(client, world.SdoLink());
  if (!res.ok) return fail("block download into 0x2100", res);
  r.transfer_s = static_cast<double>(world.now_ns() - t0) * 1e-9;
  r.rate_bytes_s = r.transfer_s > 0 ? r.bytes / r.transfer_s : 0;
  r.frames = world.bus().stats().frames - frames0;
  r.resent_segments = client.resent_segments();

  res = Write(world, ObjectId::kTableControl, 4);
  if (!res.ok) return fail("verifying on the board (0x2101 = 4)", res);
  res = Read(world, ObjectId::kStagedTableCrc, &r.staged_crc);
  if (!res.ok) return fail("reading the staged CRC-32 (0x2105)", res);
  if (r.staged_crc != r.image_crc) {
    r.message =
        "the board staged CRC-32 " + Hex32(r.staged_crc) + ", expected " + Hex32(r.image_crc);
    return r;
  }
  r.ok = true;
  r.message = "staged and verified";
  return r;
}

ActivationReport ActivateTable(World& world, uint32_t expected_crc) {
  ActivationReport r;
  SdoResult res = Write(world, ObjectId::kTableControl, 1);
  if (!res.ok) {
    r.message = "activating (0x2101 = 1): " + res.message;
    if (res.abort_code == canopen::kAbortDeviceState) {
      r.message += "; the axes must be referenced (homed) and at rest";
    }
    return r;
  }
  res = Read(world, ObjectId::kActiveTableCrc, &r.active_crc);
  if (!res.ok) {
    r.message = "reading the active CRC-32 (0x2104): " + res.message;
    return r;
  }
  r.device_state = ReadDeviceState(world);
  r.ok = r.active_crc == expected_crc;
  r.message = r.ok ? "active" : "the active CRC-32 is " + Hex32(r.active_crc);
  return r;
}

uint16_t ReadDeviceState(World& world) {
  uint32_t v = 0;
  if (!Read(world, ObjectId::kDeviceState, &v).ok) return 0;
  return static_cast<uint16_t>(v);
}

}  // namespace volcomp::sim
