// `volcomp status [--json]`: a board's identity, state, tables, per-axis positions and
// corrections, the thermal correction and its channels, and counters (board_snapshot.hpp), as one
// JSON document and its text layout.
#include <chrono>
#include <cstdio>
#include <ostream>

#include "board_snapshot.hpp"
#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using tools::Hex32;

const char* StagedStateName(canopen::StagedState s) {
  return s < canopen::StagedState::kCount ? canopen::kStagedStateNames[static_cast<int>(s)] : "?";
}

JsonValue StatusData(uint8_t node, const Snapshot& n, const std::vector<AxisInfo>& axes) {
  const canopen::TableStatus table = canopen::DecodeTableStatus(n.table_status);
  const canopen::DeviceState state = canopen::DecodeDeviceState(static_cast<uint16_t>(n.state));
  JsonValue d = JsonValue::Object();
  d.Set("node", unsigned{node});
  d.Set("device_name", n.device_name);
  d.Set("software_version", n.software_version);
  d.Set("vendor_id", Hex32(n.vendor));
  d.Set("product_code", Hex32(n.product));
  d.Set("revision", Hex32(n.revision));
  d.Set("serial_number", uint64_t{n.serial});
  if (n.nmt) d.Set("nmt_state", canopen_client::NmtStateName(*n.nmt));
  d.Set("device_state", uint64_t{n.state});
  d.Set("device_state_flags", StateText(n.state));
  d.Set("writable", n.writable != 0);
  JsonValue& active = d["active_table"] = JsonValue::Object();
  active.Set("present", state.table_active);
  active.Set("id", uint64_t{n.active_id});
  active.Set("crc32", Hex32(n.active_crc));
  JsonValue& staged = d["staged_table"] = JsonValue::Object();
  staged.Set("state", StagedStateName(table.staged));
  staged.Set("bytes", uint64_t{n.staged_bytes});
  staged.Set("id", uint64_t{n.staged_id});
  staged.Set("crc32", Hex32(n.staged_crc));
  staged.Set("last_error", ErrorName(table.error));
  staged.Set("has_image", table.staged == canopen::StagedState::kComplete ||
                              table.staged == canopen::StagedState::kVerified);
  staged.Set("last_error_text", ErrorText(table.error));
  d.Set("settings_pending", state.settings_pending);
  JsonValue& list = d["axes"] = JsonValue::Array();
  for (uint32_t a = 0; a < axes.size(); ++a) {
    list.Push(AxisData(n, axes[a], a, state.referenced));
  }
  if (n.thermal) d.Set("thermal", ThermalData(*n.thermal, axes));
  d.Set("counters", CountersData(n));
  return d;
}

// What bounds the correction of an axis now, for its line ("" when nothing does): at the max
// correction (0x2015), the board's flags (0x2134: clamped to 0x2015 or rate limited by 0x2016
// within the last 100 ms) and their counts (0x2135, 0x2136).
std::string LimitText(const JsonValue& x) {
  std::string t = x.get("at_max_correction")->boolean ? ", AT MAX CORRECTION" : "";
  if (x.get("clamped")->boolean) t += ", CLAMPED (0x2015)";
  if (x.get("rate_limited")->boolean) t += ", RATE LIMITED (0x2016)";
  const int64_t clamped = x.get("clamped_refreshes")->integer;
  const int64_t rate = x.get("rate_limited_refreshes")->integer;
  if (clamped != 0 || rate != 0) {
    t += ", limited refreshes: clamped " + std::to_string(clamped) + ", rate " +
         std::to_string(rate);
  }
  return t;
}

void AxisLine(const JsonValue& x, std::ostream& out) {
  const bool rotary = x.get("kind")->string == "rotary";
  const std::string position_unit = rotary ? "deg" : "mm";
  const double correction =
      x.get(rotary ? "applied_correction_arcsec" : "applied_correction_um")->number;
  // The machine position is the table's coordinate: the home position (0x2018) at the
  // reference point plus the input since; meaningless before referencing.
  char machine[80] = "not referenced";
  if (const JsonValue* steps = x.get("machine_steps")) {
    std::snprintf(machine, sizeof machine, "%.4f %s (%d steps)",
                  x.get("machine_" + position_unit)->number, position_unit.c_str(),
                  static_cast<int>(steps->integer));
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "axis %d %s: input %d steps, machine %s, correction %+.3f %s (%+.3f steps, max "
                "%d = %.3f %s)%s, output %d steps, max backlog %u\n",
                static_cast<int>(x.get("axis")->integer), x.get("name")->string.c_str(),
                static_cast<int>(x.get("commanded_steps")->integer), machine, correction,
                rotary ? "arcsec" : "µm", x.get("applied_correction_steps")->number,
                static_cast<int>(x.get("max_correction_steps")->integer),
                x.get(rotary ? "max_correction_arcsec" : "max_correction_um")->number,
                rotary ? "arcsec" : "µm", LimitText(x).c_str(),
                static_cast<int>(x.get("output_steps")->integer),
                static_cast<unsigned>(x.get("max_backlog_steps")->integer));
  out << line;
}

// "thermal: model in force, holding; channel 1 25.00 C valid (0 faults), ...; X offset +10.000 µm,
// slope +0.000 µm/m" (docs/thermal.md), one line.
void ThermalLine(const JsonValue& t, std::ostream& out) {
  std::string flags = t.get("model_in_force")->boolean ? "model in force" : "no model";
  for (const char* f : {"holding", "fading", "slewing", "saturated"}) {
    if (t.get(f)->boolean) flags += std::string(", ") + f;
  }
  out << "thermal: " << flags;
  const auto& channels = t.get("channels")->array;
  if (channels.empty()) out << "; no channel configured";
  for (size_t i = 0; i < channels.size(); ++i) {
    const JsonValue& c = channels[i];
    char line[96];
    std::snprintf(line, sizeof line, "%schannel %d %.2f C %s (%d faults)", i == 0 ? "; " : ", ",
                  static_cast<int>(c.get("channel")->integer), c.get("temperature_C")->number,
                  c.get("state")->string.c_str(), static_cast<int>(c.get("faults")->integer));
    out << line;
  }
  for (const JsonValue& x : t.get("axes")->array) {
    char line[96];
    std::snprintf(line, sizeof line, "; %s offset %+.3f µm, slope %+.3f µm/m",
                  x.get("name")->string.c_str(), x.get("offset_um")->number,
                  x.get("slope_um_per_m")->number);
    out << line;
  }
  out << "\n";
}

void StatusText(const JsonValue& d, std::ostream& out) {
  const JsonValue* nmt = d.get("nmt_state");
  out << "node " << d.get("node")->integer << ": " << d.get("device_name")->string << " "
      << d.get("software_version")->string << " (vendor " << d.get("vendor_id")->string
      << ", product " << d.get("product_code")->string << ", revision " << d.get("revision")->string
      << ", serial " << d.get("serial_number")->integer << ")"
      << (nmt != nullptr ? ", " + nmt->string : std::string()) << "\n";
  out << "state: " << d.get("device_state_flags")->string << "\n";
  const JsonValue& active = *d.get("active_table");
  out << "active table: "
      << (active.get("present")->boolean ? "id " + std::to_string(active.get("id")->integer) +
                                               ", CRC-32 " + active.get("crc32")->string
                                         : std::string("none (pass-through)"))
      << "\n";
  const JsonValue& staged = *d.get("staged_table");
  out << "staged table: " << staged.get("state")->string;
  if (staged.get("has_image")->boolean) {
    out << ", " << staged.get("bytes")->integer << " bytes, id " << staged.get("id")->integer
        << ", CRC-32 " << staged.get("crc32")->string;
  }
  if (staged.get("last_error")->string != ErrorName(Error::kOk)) {
    out << ", last error " << staged.get("last_error")->string << ": "
        << staged.get("last_error_text")->string;
  }
  out << "\n";
  if (d.get("settings_pending")->boolean) {
    out << "settings pending: axis names and units below are the edited values, in force after "
           "NMT reset node\n";
  }
  for (const JsonValue& x : d.get("axes")->array) AxisLine(x, out);
  if (const JsonValue* t = d.get("thermal")) ThermalLine(*t, out);
  out << "counters:";
  for (const auto& [name, value] : d.get("counters")->object)
    out << " " << name << "=" << value.integer;
  out << "\n";
}

Expected<Output> RunStatus(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  args.Flag("--json");  // the command layer prints the data as JSON
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  VOLCOMP_TRY(session->Listen(std::chrono::milliseconds(0)));
  VOLCOMP_TRY_ASSIGN(const Snapshot n, TakeSnapshot(*session));
  VOLCOMP_TRY_ASSIGN(const std::vector<AxisInfo> axes, ReadAxes(*session, n.axes));
  return Output{StatusData(can.node, n, axes), StatusText, {}};
}

}  // namespace

const Command& StatusCommand() {
  static const Command kCommand{
      "status", "a board's identity, state, tables, per-axis positions and corrections, counters",
      "",
      Join({CanOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunStatus};
  return kCommand;
}

}  // namespace volcomp::cli
