// `volcomp config apply FILE [--no-reset]`: a configuration file onto a board. The file is checked
// first (the settings file's reader and the firmware's rules: refused with its line, nothing sent);
// then the objects that differ are written and stored (1010:1), the node reset (NMT 0x81), and
// every object read back and compared. A refused write or store undoes the edits written before it.
// A new units per step is said with what it does to the home position in mm, and refused while a
// table is active unless --force (the board drops that table at the reset: it no longer matches).
// The changes and the store stream as they happen; the verdict is the command's result.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "config_view.hpp"
#include "sdo_failure.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;
using canopen_client::CanSession;
using canopen_client::Difference;

constexpr auto kBootUpWait = std::chrono::milliseconds(3000);

JsonValue Descriptions(const std::vector<Difference>& list, const BoardSettings& names) {
  JsonValue a = JsonValue::Array();
  for (const Difference& d : list) a.Push(canopen_client::DescribeDifference(d, names));
  return a;
}

// The axes whose units per step `wanted` changes, each with its home position before and after
// (steps and machine units: the same steps are another place at another resolution).
JsonValue ResolutionChanges(const BoardSettings& before, const BoardSettings& wanted) {
  JsonValue list = JsonValue::Array();
  const uint8_t n = std::min(before.board.axis_count, wanted.board.axis_count);
  for (uint8_t i = 0; i < n; ++i) {
    const AxisConfig& a = before.board.axis[i];
    const AxisConfig& b = wanted.board.axis[i];
    if (a.resolution_e9 == b.resolution_e9) continue;
    const bool rotary = b.kind == table::AxisKind::kRotary;
    const char* unit = rotary ? "deg" : "mm";
    JsonValue x = JsonValue::Object();
    x.Set("axis", unsigned{i} + 1u);
    x.Set("name", std::string(1, b.name));
    x.Set("unit", unit);
    x.Set("units_per_step_before", a.resolution_e9 * 1e-9);
    x.Set("units_per_step", b.resolution_e9 * 1e-9);
    x.Set("steps_per_unit_before", 1e9 / a.resolution_e9);  // 0x2012 is never 0 (1e-9 .. 4.29)
    x.Set("steps_per_unit", 1e9 / b.resolution_e9);
    x.Set("resolution_before", image::ResolutionText(a.resolution_e9, rotary));
    x.Set("resolution", image::ResolutionText(b.resolution_e9, rotary));
    x.Set("home_position_steps_before", int64_t{a.home_position_steps});
    x.Set("home_position_steps", int64_t{b.home_position_steps});
    x.Set("home_position_before", a.home_position_steps * (a.resolution_e9 * 1e-9));
    x.Set("home_position", b.home_position_steps * (b.resolution_e9 * 1e-9));
    list.Push(std::move(x));
  }
  return list;
}

std::string ResolutionChangeText(const JsonValue& x) {
  char line[320];
  const std::string& unit = x.get("unit")->string;
  std::snprintf(line, sizeof line,
                "axis %d %s: resolution %s -> %s; home position %lld steps = %.4f %s "
                "-> %lld steps = %.4f %s",
                static_cast<int>(x.get("axis")->integer), x.get("name")->string.c_str(),
                x.get("resolution_before")->string.c_str(), x.get("resolution")->string.c_str(),
                static_cast<long long>(x.get("home_position_steps_before")->integer),
                x.get("home_position_before")->number, unit.c_str(),
                static_cast<long long>(x.get("home_position_steps")->integer),
                x.get("home_position")->number, unit.c_str());
  return line;
}

// Writes and stores `changes` (toward `wanted`); a refusal part-way undoes the edits written so
// far. A store the board refuses by a rule of its own kind (kPulseTiming on a step/dir board,
// which the file check cannot know) is said with the values, the limit and the fix.
Expected<size_t> WriteAndStore(CanSession& s,
                               const std::vector<Difference>& changes,
                               const BoardSettings& wanted) {
  size_t written = 0;
  Outcome stored = canopen_client::WriteObjects(s, changes, &written);
  if (stored.ok()) stored = canopen_client::StoreSettings(s);
  if (stored.ok()) return written;
  Failure f = stored.error();
  if (f.code == Error::kCommunication) return Fail(f);
  const std::string why = hosted::FindingText(wanted, canopen_client::SettingsFinding(s));
  if (!why.empty()) f.message += "; the board refuses the settings: " + why;
  std::vector<Difference> undo;
  for (size_t i = 0; i < written; ++i)
    undo.push_back({changes[i].id, changes[i].to, changes[i].from});
  size_t undone = 0;
  const Outcome undid = canopen_client::WriteObjects(s, undo, &undone);
  if (!undid.ok()) {
    return Fail(Error::kInputInvalid, f.message + "; undoing the " + std::to_string(written) +
                                          " edits written failed too (" + undid.error().message +
                                          "): `volcomp nmt reset` discards them");
  }
  return Fail(Error::kInputInvalid, f.message + " (nothing stored; the " + std::to_string(written) +
                                        " edits written were undone)");
}

// Resets the node, waits for its boot-up under the node-ID of `wanted` and reads everything back.
Expected<JsonValue> ResetAndReadBack(CanSession& s, const BoardSettings& wanted, JsonValue d) {
  VOLCOMP_TRY(s.SendNmt(canopen::NmtCommand::kResetNode));
  VOLCOMP_TRY_ASSIGN(const std::optional<uint8_t> boot,
                     s.WaitForBootUp(wanted.node_id, kBootUpWait));
  if (!boot || *boot != wanted.node_id) {
    return CommunicationFailure("stored, but no boot-up of node " + std::to_string(wanted.node_id) +
                                " within 3 s after NMT reset node" +
                                (boot ? " (node " + std::to_string(*boot) + " booted)" : ""));
  }
  canopen_client::NodeObjects node(s.link(), wanted.node_id, s.options());
  VOLCOMP_TRY_ASSIGN(const BoardConfiguration after, ReadConfiguration(node));
  const std::vector<Difference> left = canopen_client::Differences(wanted, after.settings);
  JsonValue& refused = d["refused_emcy"] = JsonValue::Array();
  for (const CanFrame& f : s.TakeEmcy()) {
    canopen::Emcy e;
    if (canopen::DecodeEmcy(f, wanted.node_id, &e) && e.code == canopen::kEmcyConfigRefused) {
      JsonValue x = JsonValue::Object();
      x.Set("part", canopen::ConfigPartName(e.config_part()));
      x.Set("error", ErrorName(e.config_error()));
      refused.Push(std::move(x));
    }
  }
  d.Set("boot_node", unsigned{*boot});
  d.Set("pending_after", after.pending);
  d.Set("differences_after", Descriptions(left, after.settings));
  d.Set("outcome", left.empty() && !after.pending ? "in force" : "differs");
  return d;
}

void ApplyText(const JsonValue& d, std::ostream& out) {
  const std::string& outcome = d.get("outcome")->string;
  const int64_t node = d.get("node")->integer;
  const std::string& file = d.get("file")->string;
  if (outcome == "already in force") {
    out << "node " << node << ": the board has " << file << " in force already; nothing written\n";
    return;
  }
  if (outcome == "stored") {
    out << "not in force until NMT reset node (`volcomp nmt reset`) or power-up\n";
    return;
  }
  if (outcome == "not verified") {
    const int64_t now = d.get("bitrate_kbit")->integer,
                  before = d.get("bitrate_kbit_before")->integer;
    out << "node reset: the board now runs at " << now << " kbit/s, so it cannot be read back at "
        << before << " kbit/s: set the adapter to " << now
        << " kbit/s and check with `volcomp config show` (not verified)\n";
    return;
  }
  for (const JsonValue& e : d.get("refused_emcy")->array) {
    out << "EMCY: the stored settings were refused by the " << e.get("part")->string << " ("
        << e.get("error")->string << "): it runs the factory settings\n";
  }
  if (outcome == "differs") {
    const auto& left = d.get("differences_after")->array;
    out << "read back after the reset: " << left.size() << " objects differ from " << file
        << (d.get("pending_after")->boolean ? ", settings still pending" : "") << "\n";
    for (const JsonValue& x : left) out << "  " << x.string << "\n";
    return;
  }
  out << "node reset (boot-up as node " << d.get("boot_node")->integer << "); read back: all "
      << d.get("objects")->integer << " objects as in " << file << ", in force\n";
}

Expected<Output> RunConfigApply(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  const bool no_reset = args.Flag("--no-reset");
  const bool force = args.Flag("--force");
  args.Flag("--json");                               // the command layer prints the data as JSON
  std::ostream& msg = ctx.json ? ctx.err : ctx.out;  // with --json stdout carries the object only
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("expected one FILE");
  // Everything is checked before the board is touched.
  const hosted::IniExpected<BoardSettings> file = hosted::ReadSettingsIniFile(files[0]);
  if (!file.ok()) return Fail(file.error().ToFailure());
  const BoardSettings& wanted = *file;
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  CanSession& s = *session;
  VOLCOMP_TRY_ASSIGN(const BoardConfiguration before, ReadConfiguration(s));
  const std::vector<Difference> changes = canopen_client::Differences(before.settings, wanted);
  JsonValue d = JsonValue::Object();
  d.Set("node", unsigned{can.node});
  d.Set("file", files[0]);
  d.Set("objects", uint64_t{canopen::SettingObjects().size()});
  d.Set("changes", Descriptions(changes, wanted));
  if (changes.empty() && !before.pending) {
    d.Set("outcome", "already in force");
    return Output{std::move(d), ApplyText, {}};
  }
  JsonValue resolution = ResolutionChanges(before.settings, wanted);
  if (!resolution.array.empty()) {
    VOLCOMP_TRY_ASSIGN(const uint32_t crc,
                       ReadNumber(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)"));
    VOLCOMP_TRY_ASSIGN(const uint32_t id,
                       ReadNumber(s, ObjectId::kActiveTableId, "the active table id (0x2103)"));
    std::string what;
    for (const JsonValue& x : resolution.array) what += "\n  " + ResolutionChangeText(x);
    if (crc != 0 && !force) {
      return Fail(Error::kInvalidArgument,
                  "the file changes the units per step while table id " + std::to_string(id) +
                      " (CRC-32 " + tools::Hex32(crc) +
                      ") is active: the board drops it at the reset (it was built for the old "
                      "resolution) and the same home steps are another place:" +
                      what +
                      "\nrebuild the table for the new resolution and convert home_position_steps, "
                      "or --force; nothing written");
    }
    msg << "units per step changed"
        << (crc != 0 ? " (the active table is dropped at the reset)" : "") << ":" << what << "\n";
  }
  d["resolution_changes"] = std::move(resolution);
  d["switch_accel_bounds"] = SwitchAccelBounds(wanted);
  for (const JsonValue& x : d.get("switch_accel_bounds")->array) {
    msg << SwitchAccelBoundText(x) << "\n";
  }
  for (const JsonValue& x : d.get("changes")->array) msg << "  " << x.string << "\n";
  VOLCOMP_TRY_ASSIGN(const size_t written, WriteAndStore(s, changes, wanted));
  d.Set("written", uint64_t{written});
  msg << "node " << unsigned{can.node} << ": " << written << " objects written, stored (1010:1)\n";
  if (no_reset) {
    d.Set("outcome", "stored");
    return Output{std::move(d), ApplyText, {}};
  }
  if (wanted.bitrate_kbit != before.settings.bitrate_kbit) {
    VOLCOMP_TRY(s.SendNmt(canopen::NmtCommand::kResetNode));
    d.Set("outcome", "not verified");
    d.Set("bitrate_kbit", unsigned{wanted.bitrate_kbit});
    d.Set("bitrate_kbit_before", unsigned{before.settings.bitrate_kbit});
    return Output{std::move(d), ApplyText, {}, tools::kExitFailed};
  }
  VOLCOMP_TRY_ASSIGN(d, ResetAndReadBack(s, wanted, std::move(d)));
  const bool in_force = d.get("outcome")->string == "in force";
  return Output{std::move(d), ApplyText, {}, in_force ? tools::kExitOk : tools::kExitFailed};
}

}  // namespace

const Command& ConfigApplyCommand() {
  static const Command kCommand{
      "config apply",
      "check an INI file with the board's rules, write it, store it, reset the node, read back",
      "FILE",
      Join({CanOptions(),
            {{"--no-reset", nullptr, nullptr, nullptr, nullptr,
              "store only: in force at the next NMT reset node or power-up"},
             {"--force", nullptr, nullptr, nullptr, nullptr,
              "change the units per step although a table is active (it is dropped)"}},
            JsonResultOption()}),
      RunConfigApply,
      "The file is checked first (unknown keys, values outside the objects' limits, the\n"
      "firmware's consistency rules: refused with its line, nothing written); then the objects\n"
      "that differ are written, stored (1010:1) and the node reset (NMT 0x81); every object is\n"
      "read back and compared. Keys left out take the factory value. A refused write or store\n"
      "undoes the edits written before it."};
  return kCommand;
}

}  // namespace volcomp::cli
