// `volcomp config save FILE|- [--force]`: a board's configuration objects as an INI file
// (hosted/settings_ini.hpp), which `config apply` reads back. With "-" the file goes to stdout.
#include <sys/stat.h>

#include <ostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "config_view.hpp"
#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

bool Exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

// The file's header comments.
std::vector<std::string> Header(bool pending) {
  std::vector<std::string> header = {
      "volcomp board configuration: `volcomp config apply FILE --can ...` writes it to a board.",
      "Each key is one object (its address and unit in the comment); a key left out takes the",
      "factory value; unknown keys and values outside the board's limits are refused."};
  if (pending) {
    header.push_back("Read while settings were pending: these values were not yet in force.");
  }
  return header;
}

void SavedText(const JsonValue& d, std::ostream& out) {
  out << "node " << d.get("node")->integer << ": " << d.get("objects")->integer
      << " objects saved to " << d.get("file")->string << " (" << d.get("axes")->integer
      << " axes)\n";
}

Expected<Output> RunConfigSave(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  const bool force = args.Flag("--force");
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("expected one FILE (- = standard output)");
  const std::string& path = files[0];
  if (path != "-" && Exists(path) && !force) {
    return Fail(Error::kIoError, path + ": exists; give --force to replace it");
  }
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  VOLCOMP_TRY_ASSIGN(const BoardConfiguration c, ReadConfiguration(*session));
  if (c.pending) ctx.err << "volcomp config save: warning: " << PendingNote() << "\n";
  const std::string text = hosted::FormatSettingsIni(c.settings, Header(c.pending));
  if (path == "-") {
    ctx.out << text;
    return Output{};
  }
  if (!tools::WriteTextFile(path, text).ok()) return Fail(Error::kIoError, path + ": cannot write");
  JsonValue d = JsonValue::Object();
  d.Set("node", unsigned{can.node});
  d.Set("objects", uint64_t{canopen::SettingObjects().size()});
  d.Set("file", path);
  d.Set("axes", unsigned{c.settings.board.axis_count});
  d.Set("settings_pending", c.pending);
  return Output{std::move(d), SavedText, {}};
}

}  // namespace

const Command& ConfigSaveCommand() {
  static const Command kCommand{
      "config save",
      "write a board's configuration to an INI file",
      "FILE|-",
      Join({CanOptions(),
            {{"--force", nullptr, nullptr, nullptr, nullptr, "replace an existing FILE"}}}),
      RunConfigSave,
      "[board] and one [axis NAME] section per axis; each key's comment names its object and\n"
      "unit. `config apply` reads the file back."};
  return kCommand;
}

}  // namespace volcomp::cli
