// `volcomp config show [--all] [--json]`: every configuration object of a board with its value
// (the edited copy a store saves), the value in force (0x2124) and the factory value.
#include <cctype>
#include <cstdio>
#include <ostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "config_view.hpp"
#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/image/axis_units.hpp"

namespace volcomp::cli {
namespace {

// One row: the object, its key and axis, and its three values as numbers and as the file's text.
JsonValue ObjectData(const canopen::SettingObject& o,
                     const BoardSettings& board,
                     const BoardSettings& in_force,
                     const BoardSettings& factory) {
  const canopen::ObjectEntry& e = canopen::Entry(o.id);
  JsonValue x = JsonValue::Object();
  x.Set("object", hosted::ObjectAddress(e));
  x.Set("name", e.name);
  x.Set("key", KeyName(e));
  x.Set("axis", AxisOf(e, board));
  if (const uint8_t ch = ChannelOf(e); ch != 0) x.Set("channel", unsigned{ch});
  x.Set("value", o.get(board));
  x.Set("text", ValueText(e, o.get(board)));
  x.Set("in_force", o.get(in_force));
  x.Set("factory", o.get(factory));
  x.Set("unit", UnitOf(e));
  x.Set("in_force_text", ValueText(e, o.get(in_force)));
  x.Set("factory_text", ValueText(e, o.get(factory)));
  const hosted::SettingKey* k = hosted::SettingKeyOf(e.id);
  const uint32_t a = e.sub - 1u;
  if (k != nullptr && k->form == hosted::SettingForm::kUnitsPerStep && a < table::kMaxAxes &&
      o.get(board) > 0) {  // the value as the drive's datasheet gives it
    const bool rotary = board.board.axis[a].kind == table::AxisKind::kRotary;
    x.Set("steps_per_unit", 1e9 / static_cast<double>(o.get(board)));
    x.Set("resolution", image::ResolutionText(static_cast<uint32_t>(o.get(board)), rotary));
  }
  return x;
}

JsonValue ShowData(uint8_t node,
                   const BoardConfiguration& c,
                   const BoardSettings& in_force,
                   bool all) {
  const BoardSettings factory;  // a fresh board's
  JsonValue d = JsonValue::Object();
  d.Set("node", unsigned{node});
  d.Set("settings_pending", c.pending);
  JsonValue& objects = d["objects"] = JsonValue::Array();
  for (const canopen::SettingObject& o : canopen::SettingObjects()) {
    const std::string axis = AxisOf(canopen::Entry(o.id), c.settings);
    const bool unused_axis = !axis.empty() && std::isdigit(static_cast<unsigned char>(axis[0]));
    // A channel unused in the edited copy and in force (its source none in both).
    const uint8_t ch = ChannelOf(canopen::Entry(o.id));
    const bool unused_channel =
        ch != 0 && c.settings.temperature[ch - 1].source == thermal::ChannelSource::kNone &&
        in_force.temperature[ch - 1].source == thermal::ChannelSource::kNone;
    if (all || (!unused_axis && !unused_channel)) {
      objects.Push(ObjectData(o, c.settings, in_force, factory));
    }
  }
  d.Set("axis_count", unsigned{c.settings.board.axis_count});
  d.Set("all_axes", all);
  d["switch_accel_bounds"] = SwitchAccelBounds(in_force);
  return d;
}

void ShowText(const JsonValue& d, std::ostream& out) {
  out << "node " << d.get("node")->integer << ": "
      << (d.get("settings_pending")->boolean ? PendingNote()
                                             : "settings in force (no edit or store pending)")
      << "\n";
  char line[384];
  std::snprintf(line, sizeof line, "%-7s %-4s %-19s %-11s %-11s %-11s %s\n", "object", "axis",
                "key", "value", "in force", "factory",
                "unit (* = not the factory value, ! = not in force)");
  out << line;
  for (const JsonValue& x : d.get("objects")->array) {
    const int64_t value = x.get("value")->integer;
    const bool changed = value != x.get("factory")->integer;
    const bool not_in_force = value != x.get("in_force")->integer;
    const JsonValue* ch = x.get("channel");
    const std::string where =
        ch != nullptr ? "T" + std::to_string(ch->integer) : x.get("axis")->string;
    const JsonValue* resolution = x.get("resolution");
    std::snprintf(
        line, sizeof line, "%-7s %-4s %-19s %-11s %-11s %-11s %s%s%s%s%s%s\n",
        x.get("object")->string.c_str(), where.c_str(), x.get("key")->string.c_str(),
        x.get("text")->string.c_str(), x.get("in_force_text")->string.c_str(),
        x.get("factory_text")->string.c_str(), changed ? "* " : "", not_in_force ? "! " : "",
        x.get("unit")->string.c_str(), resolution != nullptr ? " (value: " : "",
        resolution != nullptr ? resolution->string.c_str() : "", resolution != nullptr ? ")" : "");
    out << line;
  }
  const int64_t axes = d.get("axis_count")->integer;
  if (!d.get("all_axes")->boolean && axes < table::kMaxAxes) {
    out << "(axes " << axes + 1 << ".." << unsigned{table::kMaxAxes}
        << " are not used: --all shows their objects)\n";
  }
  if (!d.get("all_axes")->boolean) {
    out << "(temperature channels without a source are not shown: --all shows their objects)\n";
  }
  for (const JsonValue& x : d.get("switch_accel_bounds")->array) {
    out << "in force, " << SwitchAccelBoundText(x) << "\n";
  }
}

Expected<Output> RunConfigShow(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  args.Flag("--json");  // the command layer prints the data as JSON
  const bool all = args.Flag("--all");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  VOLCOMP_TRY_ASSIGN(const BoardConfiguration c, ReadConfiguration(*session));
  VOLCOMP_TRY_ASSIGN(const BoardSettings in_force, canopen_client::ReadSettingsInForce(*session));
  return Output{ShowData(can.node, c, in_force, all), ShowText, {}};
}

}  // namespace

const Command& ConfigShowCommand() {
  static const Command kCommand{
      "config show",
      "every configuration object of a board: value, value in force, factory value",
      "",
      Join({CanOptions(),
            {{"--all", nullptr, nullptr, nullptr, nullptr,
              "also the objects of the axes beyond the axis count and of the temperature channels "
              "without a source"},
             {"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunConfigShow,
      "The values are the board's edited copy (what a store saves) beside the configuration in\n"
      "force (0x2124); they differ while settings are pending (edited or stored, applied at NMT\n"
      "reset node). See docs/user-guide.md \"Configuring the board from a file\"."};
  return kCommand;
}

}  // namespace volcomp::cli
