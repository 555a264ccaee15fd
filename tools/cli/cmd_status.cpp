// `volcomp status [--json]` and `volcomp monitor`: a board's state over CAN.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/tools/hex.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;

// 0x2140:1.. in order.
constexpr int kCounterCount =
    static_cast<int>(ObjectId::kEmcySuppressed) - static_cast<int>(ObjectId::kCanRxFrames) + 1;

// One axis as the board describes it (its configuration objects, read once) and what it does
// (the live diagnostics, read every snapshot), in steps and in machine units.
struct AxisInfo {
  char name = '?';
  bool rotary = false;
  uint32_t resolution_e9 = 0;        // units (mm or degrees) per step x 1e9, 0x2012
  int32_t max_correction_steps = 0;  // 0x2015
  // Machine units per step and the correction's display unit (µm on a linear axis, arcsec on a
  // rotary one).
  double units_per_step() const { return resolution_e9 * 1e-9; }
  const char* position_unit() const { return rotary ? "deg" : "mm"; }
  const char* correction_unit() const { return rotary ? "arcsec" : "um"; }
  double correction_per_step() const { return units_per_step() * (rotary ? 3600.0 : 1000.0); }
};

struct Snapshot {
  std::string device_name, software_version;
  uint32_t vendor = 0, product = 0, revision = 0, serial = 0;
  uint32_t state = 0, table_status = 0, active_id = 0, active_crc = 0, staged_crc = 0,
           staged_id = 0, staged_bytes = 0, writable = 0, axes = 0;
  int32_t commanded[6] = {}, machine[6] = {}, correction_q8[6] = {}, output[6] = {};
  uint32_t backlog[6] = {};
  uint32_t limit_flags[6] = {}, clamped[6] = {}, rate_limited[6] = {};  // 0x2134-0x2136
  uint32_t counters[kCounterCount] = {};
  std::optional<uint8_t> nmt;
};

ObjectId AxisObject(ObjectId first, uint32_t axis) {
  return static_cast<ObjectId>(static_cast<int>(first) + axis);
}

uint32_t Get(canopen_client::CanSession& s, ObjectId id) {
  uint32_t v = 0;
  // No answer is a communication failure (exit 3), a refusal the board's reason (exit 1).
  canopen_client::Require(s.Read(id, &v), "reading " + std::string(canopen::Entry(id).name));
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
    auto id = [a](ObjectId first) { return AxisObject(first, a); };
    n.commanded[a] = static_cast<int32_t>(Get(s, id(ObjectId::kCommandedPosition1)));
    n.machine[a] = static_cast<int32_t>(Get(s, id(ObjectId::kMachinePosition1)));
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

// The configured axes' names, kinds, units per step and maximum corrections. These read the
// board's configuration objects: while settings are pending they are the edited values.
std::vector<AxisInfo> ReadAxes(canopen_client::CanSession& s, uint32_t axes) {
  std::vector<AxisInfo> out;
  for (uint32_t a = 0; a < axes && a < 6; ++a) {
    AxisInfo x;
    x.name = static_cast<char>(Get(s, AxisObject(ObjectId::kAxisName1, a)));
    x.rotary = Get(s, AxisObject(ObjectId::kAxisKind1, a)) == 1;
    x.resolution_e9 = Get(s, AxisObject(ObjectId::kAxisResolution1, a));
    x.max_correction_steps =
        static_cast<int32_t>(Get(s, AxisObject(ObjectId::kAxisMaxCorrection1, a)));
    out.push_back(x);
  }
  return out;
}

// Whether the applied correction of axis `a` stands at its maximum correction (0x2015): the table
// asks for at least that much there, and the board applies no more.
bool AtMaxCorrection(const Snapshot& n, const AxisInfo& x, uint32_t a) {
  const int64_t applied_q8 =
      n.correction_q8[a] < 0 ? -int64_t{n.correction_q8[a]} : n.correction_q8[a];
  return x.max_correction_steps > 0 && applied_q8 >= int64_t{x.max_correction_steps} * 256;
}

// What bounds the correction of axis `a` now, for the status line ("" when nothing does): the
// board's flags (0x2134: clamped to 0x2015 or rate limited by 0x2016 within the last 100 ms) and
// their counts (0x2135, 0x2136).
std::string LimitText(const Snapshot& n, const AxisInfo& x, uint32_t a) {
  std::string t = AtMaxCorrection(n, x, a) ? ", AT MAX CORRECTION" : "";
  if ((n.limit_flags[a] & canopen::kLimitClamped) != 0) t += ", CLAMPED (0x2015)";
  if ((n.limit_flags[a] & canopen::kLimitRateLimited) != 0) t += ", RATE LIMITED (0x2016)";
  if (n.clamped[a] != 0 || n.rate_limited[a] != 0) {
    t += ", limited refreshes: clamped " + std::to_string(n.clamped[a]) + ", rate " +
         std::to_string(n.rate_limited[a]);
  }
  return t;
}

void AxisJson(JsonWriter& w, const Snapshot& n, const AxisInfo& x, uint32_t a, bool referenced) {
  w.key("axis").value(a + 1);
  w.key("name").value(std::string(1, x.name));
  w.key("kind").value(x.rotary ? "rotary" : "linear");
  w.key("units_per_step").value(x.units_per_step());
  w.key("commanded_steps").value(int64_t{n.commanded[a]});
  w.key(std::string("commanded_") + x.position_unit()).value(n.commanded[a] * x.units_per_step());
  if (referenced) {  // the table's coordinate, after the home offset (0x2018)
    w.key("machine_steps").value(int64_t{n.machine[a]});
    w.key(std::string("machine_") + x.position_unit()).value(n.machine[a] * x.units_per_step());
  }
  w.key("applied_correction_steps").value(n.correction_q8[a] / 256.0);
  w.key(std::string("applied_correction_") + x.correction_unit())
      .value(n.correction_q8[a] / 256.0 * x.correction_per_step());
  w.key("max_correction_steps").value(int64_t{x.max_correction_steps});
  w.key("at_max_correction").value(AtMaxCorrection(n, x, a));
  w.key("clamped").value((n.limit_flags[a] & canopen::kLimitClamped) != 0);
  w.key("rate_limited").value((n.limit_flags[a] & canopen::kLimitRateLimited) != 0);
  w.key("clamped_refreshes").value(uint64_t{n.clamped[a]});
  w.key("rate_limited_refreshes").value(uint64_t{n.rate_limited[a]});
  w.key("output_steps").value(int64_t{n.output[a]});
  w.key("max_backlog_steps").value(uint64_t{n.backlog[a]});
}

const char* kCounterNames[] = {
    "can_rx_frames", "can_tx_frames",   "malformed_frames", "sdo_aborts",      "emcy_sent",
    "ticks",         "output_overruns", "max_tick_cost_ns", "refused_actions", "emcy_suppressed"};
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
  const canopen::DeviceState state = canopen::DecodeDeviceState(static_cast<uint16_t>(n.state));
  const bool table_active = state.table_active;
  const std::vector<AxisInfo> axes = ReadAxes(*s, n.axes);
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
    w.key("settings_pending").value(state.settings_pending);
    w.key("axes").begin_array();
    for (uint32_t a = 0; a < axes.size(); ++a) {
      w.begin_object();
      AxisJson(w, n, axes[a], a, state.referenced);
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
  if (state.settings_pending) {
    std::printf(
        "settings pending: axis names and units below are the edited values, in force "
        "after NMT reset node\n");
  }
  for (uint32_t a = 0; a < axes.size(); ++a) {
    const AxisInfo& x = axes[a];
    const double correction_steps = n.correction_q8[a] / 256.0;
    // The machine position is the table's coordinate: the home position (0x2018) at the
    // reference point plus the input since; meaningless before referencing.
    char machine[80] = "not referenced";
    if (state.referenced) {
      std::snprintf(machine, sizeof machine, "%.4f %s (%d steps)",
                    n.machine[a] * x.units_per_step(), x.position_unit(), n.machine[a]);
    }
    std::printf(
        "axis %u %c: input %d steps, machine %s, correction %+.3f %s (%+.3f steps, max %d)%s, "
        "output %d steps, max backlog %u\n",
        a + 1, x.name, n.commanded[a], machine, correction_steps * x.correction_per_step(),
        x.rotary ? "arcsec" : "µm", correction_steps, x.max_correction_steps,
        LimitText(n, x, a).c_str(), n.output[a], n.backlog[a]);
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
  const bool csv = args.flag("--csv");
  const bool json = args.flag("--json");
  args.finish();
  if (interval < 50) throw UsageError("--interval-ms must be at least 50");
  if (csv && json) throw UsageError("--csv and --json: choose one");
  auto s = OpenSession(can);
  const auto start = std::chrono::steady_clock::now();
  std::optional<uint8_t> last_nmt;
  // With --csv or --json, stdout carries only the data; heartbeat and EMCY lines go to stderr.
  FILE* events = csv || json ? stderr : stdout;
  std::vector<AxisInfo> axes;
  if (csv || json) axes = ReadAxes(*s, Get(*s, ObjectId::kAxisCountConfig));
  if (csv) {
    std::printf("time_s,state");
    for (const AxisInfo& x : axes) {
      std::printf(
          ",%c_commanded_%s,%c_correction_%s,%c_correction_steps,%c_at_max_correction,%c_clamped,"
          "%c_rate_limited",
          x.name, x.position_unit(), x.name, x.correction_unit(), x.name, x.name, x.name, x.name);
    }
    std::printf(",output_overruns,refused_actions,sdo_aborts\n");
    std::fflush(stdout);
  }
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
      if (canopen::DecodeEmcy(f, can.node, &e)) std::fprintf(events, "%s\n", EmcyText(e).c_str());
    }
    if (s->nmt_state() != last_nmt && s->nmt_state()) {
      std::fprintf(events, "heartbeat: %s\n",
                   canopen_client::NmtStateName(*s->nmt_state()).c_str());
      last_nmt = s->nmt_state();
    }
    const Snapshot n = Take(*s, true);
    if (csv) {
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // One row per interval in machine units; the state flags joined with '+'.
      std::string state = StateText(n.state);
      for (char& c : state) c = c == ',' ? '+' : c;
      std::printf("%.3f,%s", t, state.c_str());
      for (uint32_t a = 0; a < axes.size(); ++a) {
        const double steps = n.correction_q8[a] / 256.0;
        std::printf(",%.6f,%.4f,%.4f,%d,%d,%d", n.commanded[a] * axes[a].units_per_step(),
                    steps * axes[a].correction_per_step(), steps,
                    AtMaxCorrection(n, axes[a], a) ? 1 : 0,
                    (n.limit_flags[a] & canopen::kLimitClamped) != 0 ? 1 : 0,
                    (n.limit_flags[a] & canopen::kLimitRateLimited) != 0 ? 1 : 0);
      }
      std::printf(",%u,%u,%u\n", n.counters[6], n.counters[8], n.counters[3]);
    } else if (json) {  // one object per line (JSON lines), the axes as in `status --json`
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const bool referenced = canopen::DecodeDeviceState(static_cast<uint16_t>(n.state)).referenced;
      std::ostringstream line;
      {
        JsonWriter w(line);
        w.begin_object();
        w.key("time_s").value(t);
        w.key("device_state_flags").value(StateText(n.state));
        w.key("axes").begin_array();
        for (uint32_t a = 0; a < axes.size(); ++a) {
          w.begin_object();
          AxisJson(w, n, axes[a], a, referenced);
          w.end_object();
        }
        w.end_array();
        w.key("counters").begin_object();
        for (int i = 0; i < kCounterCount; ++i)
          w.key(kCounterNames[i]).value(uint64_t{n.counters[i]});
        w.end_object();
        w.end_object();
      }
      std::string text = line.str();
      text.erase(std::remove(text.begin(), text.end(), '\n'), text.end());
      std::printf("%s\n", text.c_str());
    } else {
      std::printf("state %s |", StateText(n.state).c_str());
      for (uint32_t a = 0; a < n.axes && a < 6; ++a) {
        std::printf(" a%u %d%+.2f", a + 1, n.commanded[a], n.correction_q8[a] / 256.0);
      }
      std::printf(" | rx %u tx %u aborts %u\n", n.counters[0], n.counters[1], n.counters[3]);
    }
    std::fflush(stdout);
    if (duration > 0 && std::chrono::steady_clock::now() >= deadline) return 0;
  }
}

}  // namespace volcomp::tools
