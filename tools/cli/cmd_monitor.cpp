// `volcomp monitor`: follows a board, one line every interval (text, CSV rows in machine units, or
// JSON lines with the axes and the thermal correction as in `status --json`; CSV and JSON carry
// the temperature channels configured at the start), heartbeat changes and EMCYs as they come. The
// lines stream on Context::out (heartbeat and EMCY lines on Context::err with --csv and --json);
// the command reports nothing else.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "board_snapshot.hpp"
#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/thermal/temperature_channels.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;
using Clock = std::chrono::steady_clock;

enum class Format : uint8_t { kText, kCsv, kJson };

struct MonitorRequest {
  CanConnection can;
  double duration_s = 0;  // 0: until stopped
  long long interval_ms = 1000;
  Format format = Format::kText;
};

Expected<MonitorRequest> ParseMonitor(Args& args) {
  MonitorRequest req;
  VOLCOMP_TRY_ASSIGN(req.can, ParseCanOptions(args));
  req.duration_s = args.Number("--duration").value_or(0);
  req.interval_ms = args.Integer("--interval-ms").value_or(1000);
  const bool csv = args.Flag("--csv");
  const bool json = args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  if (req.interval_ms < 50) return UsageFailure("--interval-ms must be at least 50");
  if (csv && json) return UsageFailure("--csv and --json: choose one");
  req.format = csv ? Format::kCsv : json ? Format::kJson : Format::kText;
  return req;
}

// The temperature channels in use when the monitor starts (0x2151 not unused; none on firmware
// without the thermal objects), 0-based: each gets its columns for the whole run.
std::vector<uint32_t> ConfiguredChannels(const Snapshot& n) {
  std::vector<uint32_t> out;
  for (uint32_t ch = 0; n.thermal && ch < thermal::kMaxChannels; ++ch) {
    if (n.thermal->state[ch] != static_cast<uint32_t>(thermal::ChannelState::kUnused)) {
      out.push_back(ch);
    }
  }
  return out;
}

void CsvHeader(const std::vector<AxisInfo>& axes,
               const std::vector<uint32_t>& channels,
               std::ostream& out) {
  out << "time_s,state";
  for (const AxisInfo& x : axes) {
    const std::string n(1, x.name);
    out << "," << n << "_commanded_" << x.position_unit() << "," << n << "_machine_"
        << x.position_unit() << "," << n << "_correction_" << x.correction_unit() << "," << n
        << "_correction_steps," << n << "_at_max_correction," << n << "_clamped," << n
        << "_rate_limited";
  }
  for (uint32_t ch : channels) out << ",T" << ch + 1 << "_C,T" << ch + 1 << "_state";
  out << ",output_overruns,refused_actions,sdo_aborts\n" << std::flush;
}

// One row per interval in machine units; the state flags joined with '+'.
// A channel's cells: its temperature (C, held through a fault) and state (0x2150, 0x2151).
void CsvRow(double t,
            const Snapshot& n,
            const std::vector<AxisInfo>& axes,
            const std::vector<uint32_t>& channels,
            std::ostream& out) {
  std::string state = StateText(n.state);
  std::replace(state.begin(), state.end(), ',', '+');
  char cell[128];
  std::snprintf(cell, sizeof cell, "%.3f,%s", t, state.c_str());
  out << cell;
  const bool referenced = canopen::DecodeDeviceState(static_cast<uint16_t>(n.state)).referenced;
  for (uint32_t a = 0; a < axes.size(); ++a) {
    const double steps = n.correction_q8[a] / 256.0;
    char machine[32] = "";  // empty until the axes are referenced
    if (referenced)
      std::snprintf(machine, sizeof machine, "%.6f", n.machine[a] * axes[a].units_per_step());
    std::snprintf(cell, sizeof cell, ",%.6f,%s,%.4f,%.4f,%d,%d,%d",
                  n.commanded[a] * axes[a].units_per_step(), machine,
                  steps * axes[a].correction_per_step(), steps,
                  AtMaxCorrection(n, axes[a], a) ? 1 : 0,
                  (n.limit_flags[a] & canopen::kLimitClamped) != 0 ? 1 : 0,
                  (n.limit_flags[a] & canopen::kLimitRateLimited) != 0 ? 1 : 0);
    out << cell;
  }
  for (uint32_t ch : channels) {
    if (!n.thermal) {
      out << ",,";
      continue;
    }
    std::snprintf(
        cell, sizeof cell, ",%.2f,%s", n.thermal->temperature_cC[ch] / 100.0,
        thermal::ChannelStateName(static_cast<thermal::ChannelState>(n.thermal->state[ch])));
    out << cell;
  }
  out << "," << n.counters[kOutputOverrunCounter] << "," << n.counters[kRefusedActionCounter] << ","
      << n.counters[kSdoAbortCounter] << "\n";
}

// One object per line (JSON lines), the axes as in `status --json`.
void JsonLine(double t, const Snapshot& n, const std::vector<AxisInfo>& axes, std::ostream& out) {
  const bool referenced = canopen::DecodeDeviceState(static_cast<uint16_t>(n.state)).referenced;
  JsonValue line = JsonValue::Object();
  line.Set("time_s", t);
  line.Set("device_state_flags", StateText(n.state));
  JsonValue& list = line["axes"] = JsonValue::Array();
  for (uint32_t a = 0; a < axes.size(); ++a) list.Push(AxisData(n, axes[a], a, referenced));
  if (n.thermal) line.Set("thermal", ThermalData(*n.thermal, axes));
  line.Set("counters", CountersData(n));
  tools::WriteJson(line, out, /*compact=*/true);
}

// Per axis: its name, the machine position once referenced (else the input), the correction in
// µm (arcsec) and steps, and the limit in force.
void TextLine(const Snapshot& n, const std::vector<AxisInfo>& axes, std::ostream& out) {
  char cell[160];
  const bool referenced = canopen::DecodeDeviceState(static_cast<uint16_t>(n.state)).referenced;
  out << "state " << StateText(n.state) << " |";
  for (uint32_t a = 0; a < axes.size(); ++a) {
    const AxisInfo& x = axes[a];
    const double steps = n.correction_q8[a] / 256.0;
    const char* limit = (n.limit_flags[a] & canopen::kLimitClamped) != 0       ? " CLAMPED"
                        : (n.limit_flags[a] & canopen::kLimitRateLimited) != 0 ? " RATE LIMITED"
                                                                               : "";
    std::snprintf(cell, sizeof cell, " %c %s %.4f %s, correction %+.2f %s (%+.2f steps)%s |",
                  x.name, referenced ? "machine" : "input",
                  (referenced ? n.machine[a] : n.commanded[a]) * x.units_per_step(),
                  x.position_unit(), steps * x.correction_per_step(), x.correction_unit(), steps,
                  limit);
    out << cell;
  }
  out << " | rx " << n.counters[kCanRxCounter] << " tx " << n.counters[kCanTxCounter] << " aborts "
      << n.counters[kSdoAbortCounter] << "\n";
}

// The EMCYs and the heartbeat changes the session saw since the last call.
void Events(canopen_client::CanSession& s,
            uint8_t node,
            std::optional<uint8_t>* last_nmt,
            std::ostream& out) {
  for (const CanFrame& f : s.TakeEmcy()) {
    canopen::Emcy e;
    if (canopen::DecodeEmcy(f, node, &e)) out << EmcyText(e) << "\n";
  }
  if (s.nmt_state() && s.nmt_state() != *last_nmt) {
    out << "heartbeat: " << canopen_client::NmtStateName(*s.nmt_state()) << "\n";
    *last_nmt = s.nmt_state();
  }
}

Expected<Output> RunMonitor(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(const MonitorRequest req, ParseMonitor(args));
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(req.can));
  canopen_client::CanSession& s = *session;
  const auto start = Clock::now();
  // With --csv or --json, stdout carries only the data; heartbeat and EMCY lines go to stderr.
  std::ostream& events = req.format == Format::kText ? ctx.out : ctx.err;
  VOLCOMP_TRY_ASSIGN(
      const uint32_t count,
      ReadNumber(s, ObjectId::kAxisCountConfig, canopen::Entry(ObjectId::kAxisCountConfig).name));
  VOLCOMP_TRY_ASSIGN(const std::vector<AxisInfo> axes, ReadAxes(s, count));
  std::vector<uint32_t> channels;
  if (req.format == Format::kCsv) {
    VOLCOMP_TRY_ASSIGN(const Snapshot first, TakeSnapshot(s));
    channels = ConfiguredChannels(first);
    CsvHeader(axes, channels, ctx.out);
  }
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(req.duration_s));
  std::optional<uint8_t> last_nmt;
  for (;;) {
    auto wait = std::chrono::milliseconds(req.interval_ms);  // --duration cuts the last one short
    if (req.duration_s > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      wait = std::max(std::chrono::milliseconds(0), std::min(wait, left));
    }
    VOLCOMP_TRY(s.Listen(wait));
    Events(s, req.can.node, &last_nmt, events);
    VOLCOMP_TRY_ASSIGN(const Snapshot n, TakeSnapshot(s));
    const double t = std::chrono::duration<double>(Clock::now() - start).count();
    switch (req.format) {
      case Format::kCsv:
        CsvRow(t, n, axes, channels, ctx.out);
        break;
      case Format::kJson:
        JsonLine(t, n, axes, ctx.out);
        break;
      case Format::kText:
        TextLine(n, axes, ctx.out);
        break;
    }
    ctx.out << std::flush;
    if (req.duration_s > 0 && Clock::now() >= deadline) return Output{};
  }
}

}  // namespace

const Command& MonitorCommand() {
  static const Command kCommand{
      "monitor", "follow a board: heartbeat, EMCY and diagnostics every interval", "",
      Join({CanOptions(),
            {{"--interval-ms", nullptr, "N", "ms", "1000", "time between lines, at least 50"},
             {"--duration", nullptr, "S", "s", "0", "stop after S seconds (0 = until stopped)"},
             {"--csv", nullptr, nullptr, nullptr, nullptr,
              "CSV for logging: a header, then one row per interval in machine units (mm, µm; "
              "deg, arcsec on rotary axes), with Tn_C and Tn_state for each temperature channel "
              "in use at the start; heartbeat and EMCY lines on stderr"},
             {"--json", nullptr, nullptr, nullptr, nullptr,
              "one JSON object per interval and line (the axes and the thermal correction as in "
              "`status --json`); heartbeat and EMCY lines on stderr"}}}),
      RunMonitor};
  return kCommand;
}

}  // namespace volcomp::cli
