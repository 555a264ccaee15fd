// `volcomp status [--json]` and `volcomp monitor`: a board's state over CAN.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/status.hpp"
#include "volcomp/tools/hex.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;

// 0x2140:1.. in order.
constexpr int kCounterCount =
    static_cast<int>(ObjectId::kEmcySuppressed) - static_cast<int>(ObjectId::kCanRxFrames) + 1;

struct Snapshot {
  std::string device_name, software_version;
  uint32_t vendor = 0, product = 0, revision = 0, serial = 0;
  uint32_t state = 0, table_status = 0, active_id = 0, active_crc = 0, staged_crc = 0,
           staged_id = 0, staged_bytes = 0, writable = 0, axes = 0;
  int32_t commanded[6] = {}, correction_q8[6] = {}, output[6] = {};
  uint32_t backlog[6] = {};
  uint32_t limit_flags[6] = {}, clamped[6] = {}, rate_limited[6] = {};  // 0x2134-0x2136
  uint32_t counters[kCounterCount] = {};
  std::optional<uint8_t> nmt;
};

uint32_t Get(canopen_client::CanSession& s, ObjectId id) {
  uint32_t v = 0;
  const auto r = s.Read(id, &v);
  if (!r.ok) throw InputError("reading " + std::string(canopen::Entry(id).name) + ": " + r.message);
  return v;
}

Snapshot Take(canopen_client::CanSession& s, bool axes_detail) {
  Snapshot n;
  s.ReadString(ObjectId::kDeviceName, &n.device_name);
  s.ReadString(ObjectId::kSoftwareVersion, &n.software_version);
  n.vendor = Get(s, ObjectId::kVendorId);
  n.product = Get(s, ObjectId::kProductCode);
  n.revision = Get(s, ObjectId::kRevision);
  n.serial = Get(s, ObjectId::kSerialNumber);
  n.state = Get(s, ObjectId::kDeviceState);
  n.table_status = Get(s, ObjectId::kTableStatus);
  n.active_id = Get(s, ObjectId::kActiveTableId);
  n.active_crc = Get(s, ObjectId::kActiveTableCrc);
  n.staged_crc = Get(s, ObjectId::kStagedTableCrc);
  n.staged_id = Get(s, ObjectId::kStagedTableId);
  n.staged_bytes = Get(s, ObjectId::kStagedBytes);
  n.writable = Get(s, ObjectId::kWriteAccess);
  n.axes = Get(s, ObjectId::kAxisCountConfig);
  const uint32_t axes = n.axes > 6 ? 6 : n.axes;
  for (uint32_t a = 0; a < axes && axes_detail; ++a) {
    auto id = [a](ObjectId first) { return static_cast<ObjectId>(static_cast<int>(first) + a); };
    n.commanded[a] = static_cast<int32_t>(Get(s, id(ObjectId::kCommandedPosition1)));
    n.correction_q8[a] = static_cast<int32_t>(Get(s, id(ObjectId::kAppliedCorrection1)));
    n.output[a] = static_cast<int32_t>(Get(s, id(ObjectId::kOutputPosition1)));
    n.backlog[a] = Get(s, id(ObjectId::kMaxBacklog1));
    n.limit_flags[a] = Get(s, id(ObjectId::kCorrectionLimited1));
    n.clamped[a] = Get(s, id(ObjectId::kClampedRefreshes1));
    n.rate_limited[a] = Get(s, id(ObjectId::kRateLimitedRefreshes1));
  }
  for (int i = 0; i < kCounterCount; ++i) {
    n.counters[i] = Get(s, static_cast<ObjectId>(static_cast<int>(ObjectId::kCanRxFrames) + i));
  }
  n.nmt = s.nmt_state();
  return n;
}

const char* kCounterNames[] = {
    "can_rx_frames", "can_tx_frames",    "malformed_frames", "sdo_aborts",      "emcy_sent",
    "ticks",         "lost_step_checks", "max_tick_cost_ns", "refused_actions", "emcy_suppressed"};
static_assert(sizeof(kCounterNames) / sizeof(kCounterNames[0]) == kCounterCount,
              "one name per counter of 0x2140");

std::string StateText(uint32_t state) {
  std::string s;
  for (int b = 0; b < canopen::kDeviceStateBitCount; ++b) {
    if (state & (1u << b)) {
      s += std::string(s.empty() ? "" : ",") + canopen::kDeviceStateBitNames[b];
    }
  }
  return s.empty() ? "-" : s;
}

// `e` for people: the code, the register, the data and what the board's codes mean.
std::string EmcyText(const canopen::Emcy& e) {
  char b[96];
  std::snprintf(b, sizeof b, "EMCY 0x%04X register 0x%02X data %02X %02X %02X %02X %02X", e.code,
                e.error_register, e.data[0], e.data[1], e.data[2], e.data[3], e.data[4]);
  std::string s = b;
  if (e.code == canopen::kEmcyEStop) s += " (e-stop)";
  if (e.code == canopen::kEmcyDriveAlarm) s += " (drive alarm)";
  if (e.code == canopen::kEmcyConfigRefused) {
    s += std::string(" (settings refused by the ") + canopen::ConfigPartName(e.config_part()) +
         ": " + ErrorName(e.config_error()) + ")";
  }
  if (e.code == canopen::kEmcyRefused)
    s += " (refused action: abort " + Hex32(canopen::Code(e.abort_code())) + ")";
  if (e.code == canopen::kEmcyTableInvalid)
    s += std::string(" (table invalid: ") + ErrorName(e.error()) + ")";
  if (e.code == canopen::kEmcyCorrectionLimited) {
    char axes[64];
    std::snprintf(axes, sizeof axes,
                  " (correction limited: clamped axes 0x%02X, rate limited 0x%02X)",
                  e.clamped_axes(), e.rate_limited_axes());
    s += axes;
  }
  if (e.code == canopen::kEmcyErrorReset) s += " (errors cleared)";
  return s;
}

const char* StagedStateName(canopen::StagedState s) {
  return s < canopen::StagedState::kCount ? canopen::kStagedStateNames[static_cast<int>(s)] : "?";
}

}  // namespace

int RunStatus(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool json = args.flag("--json");
  args.finish();
  auto s = OpenSession(can);
  s->Listen(std::chrono::milliseconds(0));
  const Snapshot n = Take(*s, true);
  const canopen::TableStatus table = canopen::DecodeTableStatus(n.table_status);
  const canopen::StagedState staged_state = table.staged;
  const Error last = table.error;
  const bool table_active = canopen::DecodeDeviceState(n.state).table_active;
  if (json) {
    JsonWriter w(std::cout);
    w.begin_object();
    w.key("node").value(unsigned{can.node});
    w.key("device_name").value(n.device_name);
    w.key("software_version").value(n.software_version);
    w.key("vendor_id").value(Hex32(n.vendor));
    w.key("product_code").value(Hex32(n.product));
    w.key("revision").value(Hex32(n.revision));
    w.key("serial_number").value(uint64_t{n.serial});
    if (n.nmt) w.key("nmt_state").value(canopen_client::NmtStateName(*n.nmt));
    w.key("device_state").value(uint64_t{n.state});
    w.key("device_state_flags").value(StateText(n.state));
    w.key("writable").value(n.writable != 0);
    w.key("active_table").begin_object();
    w.key("present").value(table_active);
    w.key("id").value(uint64_t{n.active_id});
    w.key("crc32").value(Hex32(n.active_crc));
    w.end_object();
    w.key("staged_table").begin_object();
    w.key("state").value(StagedStateName(staged_state));
    w.key("bytes").value(uint64_t{n.staged_bytes});
    w.key("id").value(uint64_t{n.staged_id});
    w.key("crc32").value(Hex32(n.staged_crc));
    w.key("last_error").value(ErrorName(last));
    w.end_object();
    w.key("axes").begin_array();
    for (uint32_t a = 0; a < n.axes && a < 6; ++a) {
      w.begin_object();
      w.key("commanded_steps").value(int64_t{n.commanded[a]});
      w.key("applied_correction_steps").value(n.correction_q8[a] / 256.0);
      w.key("output_steps").value(int64_t{n.output[a]});
      w.key("max_backlog_steps").value(uint64_t{n.backlog[a]});
      w.key("clamped").value((n.limit_flags[a] & canopen::kLimitClamped) != 0);
      w.key("rate_limited").value((n.limit_flags[a] & canopen::kLimitRateLimited) != 0);
      w.key("clamped_refreshes").value(uint64_t{n.clamped[a]});
      w.key("rate_limited_refreshes").value(uint64_t{n.rate_limited[a]});
      w.end_object();
    }
    w.end_array();
    w.key("counters").begin_object();
    for (int i = 0; i < kCounterCount; ++i) w.key(kCounterNames[i]).value(uint64_t{n.counters[i]});
    w.end_object();
    w.end_object();
    return 0;
  }
  std::printf("node %u: %s %s (vendor %s, product %s, revision %s, serial %u)%s\n", can.node,
              n.device_name.c_str(), n.software_version.c_str(), Hex32(n.vendor).c_str(),
              Hex32(n.product).c_str(), Hex32(n.revision).c_str(), n.serial,
              n.nmt ? (", " + canopen_client::NmtStateName(*n.nmt)).c_str() : "");
  std::printf("state: %s\n", StateText(n.state).c_str());
  std::printf(
      "active table: %s\n",
      table_active
          ? ("id " + std::to_string(n.active_id) + ", CRC-32 " + Hex32(n.active_crc)).c_str()
          : "none (pass-through)");
  const bool staged_image = staged_state == canopen::StagedState::kComplete ||
                            staged_state == canopen::StagedState::kVerified;
  std::printf(
      "staged table: %s%s%s\n", StagedStateName(staged_state),
      staged_image ? (", " + std::to_string(n.staged_bytes) + " bytes, id " +
                      std::to_string(n.staged_id) + ", CRC-32 " + Hex32(n.staged_crc))
                         .c_str()
                   : "",
      last != Error::kOk
          ? (std::string(", last error ") + ErrorName(last) + ": " + ErrorText(last)).c_str()
          : "");
  for (uint32_t a = 0; a < n.axes && a < 6; ++a) {
    std::printf("axis %u: commanded %d, correction %+.3f, output %d steps, max backlog %u\n", a + 1,
                n.commanded[a], n.correction_q8[a] / 256.0, n.output[a], n.backlog[a]);
    std::printf(
        "axis %u: %s%s%s, clamped refreshes %u, rate-limited refreshes %u\n", a + 1,
        n.limit_flags[a] == 0 ? "correction not limited" : "CORRECTION LIMITED:",
        (n.limit_flags[a] & canopen::kLimitClamped) != 0 ? " clamped (0x2015)" : "",
        (n.limit_flags[a] & canopen::kLimitRateLimited) != 0 ? " rate limited (0x2016)" : "",
        n.clamped[a], n.rate_limited[a]);
  }
  std::printf("counters:");
  for (int i = 0; i < kCounterCount; ++i) std::printf(" %s=%u", kCounterNames[i], n.counters[i]);
  std::printf("\n");
  return 0;
}

int RunMonitor(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const double duration = args.number("--duration").value_or(0);
  const long long interval = args.integer("--interval-ms").value_or(1000);
  args.finish();
  if (interval < 50) throw UsageError("--interval-ms must be at least 50");
  auto s = OpenSession(can);
  const auto start = std::chrono::steady_clock::now();
  std::optional<uint8_t> last_nmt;
  const auto deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                    std::chrono::duration<double>(duration));
  for (;;) {
    auto wait = std::chrono::milliseconds(interval);  // --duration cuts the last wait short
    if (duration > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      wait = std::max(std::chrono::milliseconds(0), std::min(wait, left));
    }
    s->Listen(wait);
    for (const CanFrame& f : s->TakeEmcy()) {
      canopen::Emcy e;
      if (canopen::DecodeEmcy(f, can.node, &e)) std::printf("%s\n", EmcyText(e).c_str());
    }
    if (s->nmt_state() != last_nmt && s->nmt_state()) {
      std::printf("heartbeat: %s\n", canopen_client::NmtStateName(*s->nmt_state()).c_str());
      last_nmt = s->nmt_state();
    }
    const Snapshot n = Take(*s, true);
    std::printf("state %s |", StateText(n.state).c_str());
    for (uint32_t a = 0; a < n.axes && a < 6; ++a) {
      std::printf(" a%u %d%+.2f", a + 1, n.commanded[a], n.correction_q8[a] / 256.0);
    }
    std::printf(" | rx %u tx %u aborts %u\n", n.counters[0], n.counters[1], n.counters[3]);
    std::fflush(stdout);
    if (duration > 0 && std::chrono::steady_clock::now() >= deadline) return 0;
  }
}

}  // namespace volcomp::tools
