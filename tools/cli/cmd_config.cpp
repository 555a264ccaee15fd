// `volcomp config show|save|apply`: the board's configuration objects as a table, as an INI file,
// and from an INI file (validated with the firmware's rules, written, stored, node reset, read
// back). `volcomp nmt`: NMT commands with their confirmation.
#include <sys/stat.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/canopen_client/can_session.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;
using canopen_client::NmtCommand;
using hosted::SettingKey;

constexpr auto kBootUpWait = std::chrono::milliseconds(3000);

bool Exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

// The axis a configuration object belongs to ("X", "4 (not used)"), "" for board objects.
std::string AxisOf(const canopen::ObjectEntry& e, const BoardSettings& s) {
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  if (k == nullptr || e.id == ObjectId::kAxisCountConfig ||
      !(k->per_axis || k->form == hosted::SettingForm::kAxisNames)) {
    return "";
  }
  const uint32_t a = e.sub - 1u;
  return a < s.board.axis_count ? std::string(1, s.board.axis[a].name) : std::to_string(e.sub);
}

std::string KeyName(const canopen::ObjectEntry& e) {
  if (e.id == ObjectId::kAxisCountConfig) return "axes (count)";
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  if (k == nullptr) return e.name;
  return k->form == hosted::SettingForm::kAxisNames ? "axes (name)" : k->key;
}

std::string ValueText(const canopen::ObjectEntry& e, int64_t v) {
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  if (k == nullptr || e.id == ObjectId::kAxisCountConfig) return std::to_string(v);
  return hosted::FormatSettingValue(*k, v);
}

const char* PendingNote() {
  return "settings pending: these values are edited or stored but not in force until NMT reset "
         "node (`volcomp nmt reset`; edits not stored are then lost)";
}

}  // namespace

int RunConfigShow(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool json = args.flag("--json");
  const bool all = args.flag("--all");
  args.finish();
  auto s = OpenSession(can);
  const BoardSettings board = canopen_client::ReadSettings(*s);
  const bool pending = canopen_client::SettingsPending(*s);
  const BoardSettings in_force = canopen_client::ReadSettingsInForce(*s);
  const BoardSettings factory = BoardSettings();
  auto shown = [&](const canopen::ObjectEntry& e) {
    const std::string axis = AxisOf(e, board);
    return all || axis.empty() || !std::isdigit(static_cast<unsigned char>(axis[0]));
  };
  if (json) {
    JsonWriter w(std::cout);
    w.begin_object();
    w.key("node").value(unsigned{can.node});
    w.key("settings_pending").value(pending);
    w.key("objects").begin_array();
    for (const canopen::SettingObject& o : canopen::SettingObjects()) {
      const canopen::ObjectEntry& e = canopen::Entry(o.id);
      if (!shown(e)) continue;
      const SettingKey* k = hosted::SettingKeyOf(o.id);
      w.begin_object();
      w.key("object").value(hosted::ObjectAddress(e));
      w.key("name").value(e.name);
      w.key("key").value(KeyName(e));
      w.key("axis").value(AxisOf(e, board));
      w.key("value").value(o.get(board));
      w.key("text").value(ValueText(e, o.get(board)));
      w.key("in_force").value(o.get(in_force));
      w.key("factory").value(o.get(factory));
      w.key("unit").value(k != nullptr && e.id != ObjectId::kAxisCountConfig ? k->unit : "");
      w.end_object();
    }
    w.end_array();
    w.end_object();
    return kExitOk;
  }
  std::printf("node %u: %s\n", can.node,
              pending ? PendingNote() : "settings in force (no edit or store pending)");
  std::printf("%-7s %-4s %-19s %-11s %-11s %-11s %s\n", "object", "axis", "key", "value",
              "in force", "factory", "unit (* = not the factory value, ! = not in force)");
  for (const canopen::SettingObject& o : canopen::SettingObjects()) {
    const canopen::ObjectEntry& e = canopen::Entry(o.id);
    if (!shown(e)) continue;
    const SettingKey* k = hosted::SettingKeyOf(o.id);
    const bool changed = o.get(board) != o.get(factory);
    const bool not_in_force = o.get(board) != o.get(in_force);
    std::printf("%-7s %-4s %-19s %-11s %-11s %-11s %s%s%s\n", hosted::ObjectAddress(e).c_str(),
                AxisOf(e, board).c_str(), KeyName(e).c_str(), ValueText(e, o.get(board)).c_str(),
                ValueText(e, o.get(in_force)).c_str(), ValueText(e, o.get(factory)).c_str(),
                changed ? "* " : "", not_in_force ? "! " : "",
                k != nullptr && e.id != ObjectId::kAxisCountConfig ? k->unit : "");
  }
  if (!all && board.board.axis_count < table::kMaxAxes) {
    std::printf("(axes %u..%u are not used: --all shows their objects)\n",
                board.board.axis_count + 1u, table::kMaxAxes);
  }
  return kExitOk;
}

int RunConfigSave(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool force = args.flag("--force");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one FILE (- = standard output)");
  const std::string& path = pos[0];
  if (path != "-" && Exists(path) && !force) {
    throw InputError(path + ": exists; give --force to replace it");
  }
  auto s = OpenSession(can);
  const BoardSettings board = canopen_client::ReadSettings(*s);
  const bool pending = canopen_client::SettingsPending(*s);
  std::vector<std::string> header = {
      "volcomp board configuration: `volcomp config apply FILE --can ...` writes it to a board.",
      "Each key is one object (its address and unit in the comment); a key left out takes the",
      "factory value; unknown keys and values outside the board's limits are refused."};
  if (pending) {
    header.push_back("Read while settings were pending: these values were not yet in force.");
    std::cerr << "volcomp config save: warning: " << PendingNote() << "\n";
  }
  const std::string text = hosted::FormatSettingsIni(board, header);
  if (path == "-") {
    std::cout << text;
    return kExitOk;
  }
  std::ofstream f(path);
  f << text;
  f.close();
  if (!f) throw InputError(path + ": cannot write");
  std::printf("node %u: %zu objects saved to %s (%u axes)\n", can.node,
              canopen::SettingObjects().size(), path.c_str(), board.board.axis_count);
  return kExitOk;
}

int RunConfigApply(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool no_reset = args.flag("--no-reset");
  const auto pos = args.positionals();
  args.finish();
  if (pos.size() != 1) throw UsageError("expected one FILE");
  // Everything is checked before the board is touched.
  const hosted::IniExpected<BoardSettings> file = hosted::ReadSettingsIniFile(pos[0]);
  if (!file.ok()) throw InputError(file.error().ToString());
  const BoardSettings& wanted = *file;

  auto s = OpenSession(can);
  const BoardSettings before = canopen_client::ReadSettings(*s);
  const bool pending_before = canopen_client::SettingsPending(*s);
  const std::vector<canopen_client::Difference> changes =
      canopen_client::Differences(before, wanted);
  if (changes.empty() && !pending_before) {
    std::printf("node %u: the board has %s in force already; nothing written\n", can.node,
                pos[0].c_str());
    return kExitOk;
  }
  for (const canopen_client::Difference& d : changes) {
    std::printf("  %s\n", canopen_client::DescribeDifference(d, wanted).c_str());
  }
  // A refusal part-way leaves the objects as they were (the edits written so far are undone).
  size_t written = 0;
  try {
    canopen_client::WriteObjects(*s, changes, &written);
    canopen_client::StoreSettings(*s);
  } catch (const CommunicationError&) {
    throw;
  } catch (const std::exception& e) {
    std::vector<canopen_client::Difference> undo;
    for (size_t i = 0; i < written; ++i)
      undo.push_back({changes[i].id, changes[i].to, changes[i].from});
    try {
      size_t undone = 0;
      canopen_client::WriteObjects(*s, undo, &undone);
    } catch (const std::exception& u) {
      throw InputError(std::string(e.what()) + "; undoing the " + std::to_string(written) +
                       " edits written failed too (" + u.what() +
                       "): `volcomp nmt reset` discards them");
    }
    throw InputError(std::string(e.what()) + " (nothing stored; the " + std::to_string(written) +
                     " edits written were undone)");
  }
  std::printf("node %u: %zu objects written, stored (1010:1)\n", can.node, written);
  if (no_reset) {
    std::printf("not in force until NMT reset node (`volcomp nmt reset`) or power-up\n");
    return kExitOk;
  }
  if (wanted.bitrate_kbit != before.bitrate_kbit) {
    s->SendNmt(NmtCommand::kResetNode);
    std::printf(
        "node reset: the board now runs at %u kbit/s, so it cannot be read back at %u kbit/s: "
        "set the adapter to %u kbit/s and check with `volcomp config show` (not verified)\n",
        wanted.bitrate_kbit, before.bitrate_kbit, wanted.bitrate_kbit);
    return kExitFailed;
  }
  s->SendNmt(NmtCommand::kResetNode);
  const std::optional<uint8_t> boot = s->WaitForBootUp(wanted.node_id, kBootUpWait);
  if (!boot || *boot != wanted.node_id) {
    throw CommunicationError("stored, but no boot-up of node " + std::to_string(wanted.node_id) +
                             " within 3 s after NMT reset node" +
                             (boot ? " (node " + std::to_string(*boot) + " booted)" : ""));
  }
  canopen_client::NodeObjects node(s->link(), wanted.node_id, s->options());
  const BoardSettings after = canopen_client::ReadSettings(node);
  const bool pending_after = canopen_client::SettingsPending(node);
  const std::vector<canopen_client::Difference> left = canopen_client::Differences(wanted, after);
  for (const CanFrame& f : s->TakeEmcy()) {
    canopen::Emcy e;
    if (canopen::DecodeEmcy(f, wanted.node_id, &e) && e.code == canopen::kEmcyConfigRefused) {
      std::printf(
          "EMCY: the stored settings were refused by the %s (%s): it runs the factory "
          "settings\n",
          canopen::ConfigPartName(e.config_part()), ErrorName(e.config_error()));
    }
  }
  if (!left.empty() || pending_after) {
    std::printf("read back after the reset: %zu objects differ from %s%s\n", left.size(),
                pos[0].c_str(), pending_after ? ", settings still pending" : "");
    for (const canopen_client::Difference& d : left) {
      std::printf("  %s\n", canopen_client::DescribeDifference(d, after).c_str());
    }
    return kExitFailed;
  }
  std::printf("node reset (boot-up as node %u); read back: all %zu objects as in %s, in force\n",
              wanted.node_id, canopen::SettingObjects().size(), pos[0].c_str());
  return kExitOk;
}

int RunNmt(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const bool no_wait = args.flag("--no-wait");
  const long long wait_ms = args.integer("--wait-ms").value_or(2500);
  const auto pos = args.positionals();
  args.finish();
  if (wait_ms < 1 || wait_ms > 60000) throw UsageError("--wait-ms must be 1..60000");
  struct Choice {
    const char* word;
    NmtCommand command;
    canopen::NmtState state;  // confirmed by (heartbeat), or boot-up for the resets
    const char* what;
  };
  static const Choice kChoices[] = {
      {"reset", NmtCommand::kResetNode, canopen::NmtState::kInitialising, "reset node"},
      {"reset-comm", NmtCommand::kResetCommunication, canopen::NmtState::kInitialising,
       "reset communication"},
      {"start", NmtCommand::kStart, canopen::NmtState::kOperational, "start"},
      {"stop", NmtCommand::kStop, canopen::NmtState::kStopped, "stop"},
      {"pre-op", NmtCommand::kEnterPreOperational, canopen::NmtState::kPreOperational,
       "enter pre-operational"},
  };
  const Choice* c = nullptr;
  for (const Choice& x : kChoices) {
    if (pos.size() == 1 && pos[0] == x.word) c = &x;
  }
  if (c == nullptr) throw UsageError("expected one of reset, reset-comm, start, stop, pre-op");
  auto s = OpenSession(can);
  s->SendNmt(c->command);
  if (no_wait) {
    std::printf("node %u: %s sent (not confirmed: --no-wait)\n", can.node, c->what);
    return kExitOk;
  }
  const auto wait = std::chrono::milliseconds(wait_ms);
  if (c->state == canopen::NmtState::kInitialising) {
    const std::optional<uint8_t> boot = s->WaitForBootUp(can.node, wait);
    if (!boot) {
      throw CommunicationError(std::string(c->what) + " sent, but no boot-up within " +
                               std::to_string(wait_ms) + " ms");
    }
    if (*boot != can.node) {
      std::printf("node %u: %s: boot-up as node %u (its stored node-ID)\n", can.node, c->what,
                  *boot);
    } else {
      std::printf("node %u: %s: boot-up seen, pre-operational\n", can.node, c->what);
    }
    return kExitOk;
  }
  const std::optional<uint8_t> state = s->WaitForState(static_cast<uint8_t>(c->state), wait);
  if (!state) {
    throw CommunicationError(std::string(c->what) + " sent, but no heartbeat within " +
                             std::to_string(wait_ms) +
                             " ms to confirm it (heartbeat off? 0x1017; --no-wait only sends)");
  }
  if (*state != static_cast<uint8_t>(c->state)) {
    std::printf("node %u: %s sent, but the heartbeat reports %s\n", can.node, c->what,
                canopen_client::NmtStateName(*state).c_str());
    return kExitFailed;
  }
  std::printf("node %u: %s: heartbeat reports %s\n", can.node, c->what,
              canopen_client::NmtStateName(*state).c_str());
  return kExitOk;
}

}  // namespace volcomp::tools
