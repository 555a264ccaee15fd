// The board's state as `status` and `monitor` read it.
#include "board_snapshot.hpp"

#include <cstdio>

#include "sdo_failure.hpp"
#include "volcomp/thermal/temperature_channels.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;

// Element n (0-based) of an array object whose element 1 is `first` (per axis, per channel).
ObjectId Element(ObjectId first, uint32_t n) {
  return static_cast<ObjectId>(static_cast<int>(first) + static_cast<int>(n));
}

Expected<uint32_t> Get(canopen_client::CanSession& s, ObjectId id) {
  // No answer is a communication failure (exit 3), a refusal the board's reason (exit 1).
  return ReadNumber(s, id, canopen::Entry(id).name);
}

Expected<int32_t> GetSigned(canopen_client::CanSession& s, ObjectId id) {
  VOLCOMP_TRY_ASSIGN(const uint32_t v, Get(s, id));
  return static_cast<int32_t>(v);
}

// The thermal objects, or none when the firmware has no 0x2153 (an older board).
Expected<std::optional<ThermalSnapshot>> TakeThermal(canopen_client::CanSession& s, uint32_t axes) {
  const canopen_client::SdoExpected<uint32_t> status = s.Read(ObjectId::kThermalStatus);
  if (canopen_client::AbortOf(status) == canopen::SdoAbort::kNoObject) {
    return std::optional<ThermalSnapshot>();
  }
  ThermalSnapshot t;
  VOLCOMP_TRY_ASSIGN(t.status, Checked(status, "reading the thermal status 0x2153:1"));
  VOLCOMP_TRY_ASSIGN(t.fault_channels, Get(s, ObjectId::kThermalFaultChannels));
  VOLCOMP_TRY_ASSIGN(t.outside_channels, Get(s, ObjectId::kThermalOutsideChannels));
  VOLCOMP_TRY_ASSIGN(t.saturated_axes, Get(s, ObjectId::kThermalSaturatedAxes));
  for (uint32_t ch = 0; ch < 8; ++ch) {
    VOLCOMP_TRY_ASSIGN(t.state[ch], Get(s, Element(ObjectId::kTemperatureState1, ch)));
    if (t.state[ch] == 0) continue;  // unused
    VOLCOMP_TRY_ASSIGN(const uint32_t raw, Get(s, Element(ObjectId::kTemperature1, ch)));
    t.temperature_cC[ch] = static_cast<int16_t>(raw & 0xFFFFu);
    VOLCOMP_TRY_ASSIGN(t.faults[ch], Get(s, Element(ObjectId::kTemperatureFaults1, ch)));
  }
  if ((t.status & canopen::kThermalActive) != 0) {
    for (uint32_t a = 0; a < axes && a < 6; ++a) {
      VOLCOMP_TRY_ASSIGN(t.offset_nm[a], GetSigned(s, Element(ObjectId::kThermalOffset1, a)));
      VOLCOMP_TRY_ASSIGN(t.slope_nm_per_m[a], GetSigned(s, Element(ObjectId::kThermalSlope1, a)));
    }
  }
  return std::optional<ThermalSnapshot>(t);
}

const char* const kCounterNames[] = {
    "can_rx_frames", "can_tx_frames",   "malformed_frames", "sdo_aborts",      "emcy_sent",
    "ticks",         "output_overruns", "max_tick_cost_ns", "refused_actions", "emcy_suppressed"};
static_assert(sizeof(kCounterNames) / sizeof(kCounterNames[0]) == kCounterCount,
              "one name per counter of 0x2140");

}  // namespace

const char* const* CounterNames() { return kCounterNames; }

Expected<Snapshot> TakeSnapshot(canopen_client::CanSession& s) {
  Snapshot n;
  if (auto name = s.ReadString(ObjectId::kDeviceName); name.ok()) n.device_name = *name;
  if (auto version = s.ReadString(ObjectId::kSoftwareVersion); version.ok()) {
    n.software_version = *version;
  }
  VOLCOMP_TRY_ASSIGN(n.vendor, Get(s, ObjectId::kVendorId));
  VOLCOMP_TRY_ASSIGN(n.product, Get(s, ObjectId::kProductCode));
  VOLCOMP_TRY_ASSIGN(n.revision, Get(s, ObjectId::kRevision));
  VOLCOMP_TRY_ASSIGN(n.serial, Get(s, ObjectId::kSerialNumber));
  VOLCOMP_TRY_ASSIGN(n.state, Get(s, ObjectId::kDeviceState));
  VOLCOMP_TRY_ASSIGN(n.table_status, Get(s, ObjectId::kTableStatus));
  VOLCOMP_TRY_ASSIGN(n.active_id, Get(s, ObjectId::kActiveTableId));
  VOLCOMP_TRY_ASSIGN(n.active_crc, Get(s, ObjectId::kActiveTableCrc));
  VOLCOMP_TRY_ASSIGN(n.staged_crc, Get(s, ObjectId::kStagedTableCrc));
  VOLCOMP_TRY_ASSIGN(n.staged_id, Get(s, ObjectId::kStagedTableId));
  VOLCOMP_TRY_ASSIGN(n.staged_bytes, Get(s, ObjectId::kStagedBytes));
  VOLCOMP_TRY_ASSIGN(n.writable, Get(s, ObjectId::kWriteAccess));
  VOLCOMP_TRY_ASSIGN(n.axes, Get(s, ObjectId::kAxisCountConfig));
  const uint32_t axes = n.axes > 6 ? 6 : n.axes;
  for (uint32_t a = 0; a < axes; ++a) {
    const auto id = [a](ObjectId first) { return Element(first, a); };
    VOLCOMP_TRY_ASSIGN(n.commanded[a], GetSigned(s, id(ObjectId::kCommandedPosition1)));
    VOLCOMP_TRY_ASSIGN(n.machine[a], GetSigned(s, id(ObjectId::kMachinePosition1)));
    VOLCOMP_TRY_ASSIGN(n.correction_q8[a], GetSigned(s, id(ObjectId::kAppliedCorrection1)));
    VOLCOMP_TRY_ASSIGN(n.output[a], GetSigned(s, id(ObjectId::kOutputPosition1)));
    VOLCOMP_TRY_ASSIGN(n.backlog[a], Get(s, id(ObjectId::kMaxBacklog1)));
    VOLCOMP_TRY_ASSIGN(n.limit_flags[a], Get(s, id(ObjectId::kCorrectionLimited1)));
    VOLCOMP_TRY_ASSIGN(n.clamped[a], Get(s, id(ObjectId::kClampedRefreshes1)));
    VOLCOMP_TRY_ASSIGN(n.rate_limited[a], Get(s, id(ObjectId::kRateLimitedRefreshes1)));
  }
  for (int i = 0; i < kCounterCount; ++i) {
    VOLCOMP_TRY_ASSIGN(n.counters[i],
                       Get(s, static_cast<ObjectId>(static_cast<int>(ObjectId::kCanRxFrames) + i)));
  }
  VOLCOMP_TRY_ASSIGN(n.thermal, TakeThermal(s, axes));
  n.nmt = s.nmt_state();
  return n;
}

Expected<std::vector<AxisInfo>> ReadAxes(canopen_client::CanSession& s, uint32_t axes) {
  std::vector<AxisInfo> out;
  for (uint32_t a = 0; a < axes && a < 6; ++a) {
    AxisInfo x;
    VOLCOMP_TRY_ASSIGN(const uint32_t name, Get(s, Element(ObjectId::kAxisName1, a)));
    VOLCOMP_TRY_ASSIGN(const uint32_t kind, Get(s, Element(ObjectId::kAxisKind1, a)));
    VOLCOMP_TRY_ASSIGN(x.resolution_e9, Get(s, Element(ObjectId::kAxisResolution1, a)));
    VOLCOMP_TRY_ASSIGN(x.max_correction_steps,
                       GetSigned(s, Element(ObjectId::kAxisMaxCorrection1, a)));
    x.name = static_cast<char>(name);
    x.rotary = kind == 1;
    out.push_back(x);
  }
  return out;
}

bool AtMaxCorrection(const Snapshot& n, const AxisInfo& x, uint32_t a) {
  const int64_t applied_q8 =
      n.correction_q8[a] < 0 ? -int64_t{n.correction_q8[a]} : n.correction_q8[a];
  return x.max_correction_steps > 0 && applied_q8 >= int64_t{x.max_correction_steps} * 256;
}

JsonValue AxisData(const Snapshot& n, const AxisInfo& x, uint32_t a, bool referenced) {
  JsonValue d = JsonValue::Object();
  d.Set("axis", a + 1);
  d.Set("name", std::string(1, x.name));
  d.Set("kind", x.rotary ? "rotary" : "linear");
  d.Set("units_per_step", x.units_per_step());
  d.Set("commanded_steps", int64_t{n.commanded[a]});
  d.Set(std::string("commanded_") + x.position_unit(), n.commanded[a] * x.units_per_step());
  if (referenced) {
    d.Set("machine_steps", int64_t{n.machine[a]});
    d.Set(std::string("machine_") + x.position_unit(), n.machine[a] * x.units_per_step());
  }
  d.Set("applied_correction_steps", n.correction_q8[a] / 256.0);
  d.Set(std::string("applied_correction_") + x.correction_unit(),
        n.correction_q8[a] / 256.0 * x.correction_per_step());
  d.Set("max_correction_steps", int64_t{x.max_correction_steps});
  d.Set(std::string("max_correction_") + x.correction_unit(),
        x.max_correction_steps * x.correction_per_step());
  d.Set("at_max_correction", AtMaxCorrection(n, x, a));
  d.Set("clamped", (n.limit_flags[a] & canopen::kLimitClamped) != 0);
  d.Set("rate_limited", (n.limit_flags[a] & canopen::kLimitRateLimited) != 0);
  d.Set("clamped_refreshes", uint64_t{n.clamped[a]});
  d.Set("rate_limited_refreshes", uint64_t{n.rate_limited[a]});
  d.Set("output_steps", int64_t{n.output[a]});
  d.Set("max_backlog_steps", uint64_t{n.backlog[a]});
  return d;
}

JsonValue CountersData(const Snapshot& n) {
  JsonValue d = JsonValue::Object();
  for (int i = 0; i < kCounterCount; ++i) d.Set(kCounterNames[i], uint64_t{n.counters[i]});
  return d;
}

JsonValue ThermalData(const ThermalSnapshot& t, const std::vector<AxisInfo>& axes) {
  JsonValue d = JsonValue::Object();
  d.Set("model_in_force", (t.status & canopen::kThermalActive) != 0);
  d.Set("holding", (t.status & canopen::kThermalHolding) != 0);
  d.Set("fading", (t.status & canopen::kThermalFading) != 0);
  d.Set("slewing", (t.status & canopen::kThermalSlewing) != 0);
  d.Set("saturated", (t.status & canopen::kThermalSaturated) != 0);
  d.Set("faulted_channel_mask", uint64_t{t.fault_channels});
  d.Set("outside_range_channel_mask", uint64_t{t.outside_channels});
  d.Set("saturated_axis_mask", uint64_t{t.saturated_axes});
  JsonValue channels = JsonValue::Array();
  for (uint32_t ch = 0; ch < 8; ++ch) {
    if (t.state[ch] == 0) continue;
    JsonValue c = JsonValue::Object();
    c.Set("channel", ch + 1);
    c.Set("state", thermal::ChannelStateName(static_cast<thermal::ChannelState>(t.state[ch])));
    c.Set("temperature_C", t.temperature_cC[ch] / 100.0);
    c.Set("faults", uint64_t{t.faults[ch]});
    channels.Push(std::move(c));
  }
  d.Set("channels", std::move(channels));
  JsonValue terms = JsonValue::Array();
  if ((t.status & canopen::kThermalActive) != 0) {
    for (uint32_t a = 0; a < axes.size() && a < 6; ++a) {
      if (axes[a].rotary) continue;  // a rotary axis has no thermal term
      JsonValue x = JsonValue::Object();
      x.Set("axis", a + 1);
      x.Set("name", std::string(1, axes[a].name));
      x.Set("offset_um", t.offset_nm[a] / 1000.0);
      x.Set("slope_um_per_m", t.slope_nm_per_m[a] / 1000.0);
      terms.Push(std::move(x));
    }
  }
  d.Set("axes", std::move(terms));
  return d;
}

std::string StateText(uint32_t state) {
  std::string s;
  for (int b = 0; b < canopen::kDeviceStateBitCount; ++b) {
    if (state & (1u << b)) {
      s += std::string(s.empty() ? "" : ",") + canopen::kDeviceStateBitNames[b];
    }
  }
  return s.empty() ? "-" : s;
}

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
  if (e.code == canopen::kEmcyRefused) {
    s += " (refused action: abort " + tools::Hex32(canopen::Code(e.abort_code())) + ")";
  }
  if (e.code == canopen::kEmcyTableInvalid) {
    s += std::string(" (table invalid: ") + ErrorName(e.error()) + ")";
  }
  if (e.code == canopen::kEmcyCorrectionLimited) {
    char axes[64];
    std::snprintf(axes, sizeof axes,
                  " (correction limited: clamped axes 0x%02X, rate limited 0x%02X)",
                  e.clamped_axes(), e.rate_limited_axes());
    s += axes;
  }
  if (e.code == canopen::kEmcyTemperatureChannel) {
    char t[128];
    std::snprintf(t, sizeof t,
                  " (temperature channel fault: channels 0x%02X just faulted, 0x%02X in a fault, "
                  "state %s)",
                  e.data[0], e.data[1],
                  thermal::ChannelStateName(static_cast<thermal::ChannelState>(e.data[2])));
    s += t;
  }
  if (e.code == canopen::kEmcyThermalSaturated) {
    char t[64];
    std::snprintf(t, sizeof t, " (thermal term saturated: axes 0x%02X)", e.data[0]);
    s += t;
  }
  if (e.code == canopen::kEmcyErrorReset) s += " (errors cleared)";
  return s;
}

}  // namespace volcomp::cli
