// The command layer: dispatch, help, printing a command's Output or Failure, exit codes.
#include <algorithm>
#include <iostream>
#include <sstream>

#include "command.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::cli {
namespace {

bool Declares(const Command& c, const char* option) {
  for (const OptionSpec& o : c.options) {
    if (std::string(o.name) == option) return true;
  }
  return false;
}

// --json among the options (before "--"), for a command that declares it.
bool JsonRequested(const Command& c, const std::vector<std::string>& words) {
  return Declares(c, "--json") &&
         std::find(words.begin(), std::find(words.begin(), words.end(), "--"), "--json") !=
             words.end();
}

// With --json, a failure is a JSON object on stdout too, so a script reads one object whatever
// happened: {"command", "exit_code", "error"}.
int PrintFailure(const Command& c, const Failure& f, Context& ctx) {
  const int code = ExitCodeOf(f);
  if (code == tools::kExitUsage) {
    ctx.err << "volcomp " << c.name << ": " << f.message << "\n(`volcomp help " << c.name
            << "` lists the options)\n";
  } else {
    ctx.err << "volcomp " << c.name << ": error: " << f.message << "\n";
  }
  if (ctx.json) {
    JsonValue o = JsonValue::Object();
    o.Set("command", c.name).Set("exit_code", code).Set("error", f.message);
    WriteJson(o, ctx.out);
  }
  return code;
}

void PrintOutput(const Output& output, Context& ctx) {
  for (const std::string& w : output.warnings) ctx.err << "warning: " << w << "\n";
  if (output.data.is_null()) return;
  if (ctx.json) {
    WriteJson(output.data, ctx.out);
  } else if (output.text != nullptr) {
    output.text(output.data, ctx.out);
  }
}

}  // namespace

int ExitCodeOf(const Failure& failure) {
  switch (failure.code) {
    case Error::kUsage:
      return tools::kExitUsage;
    case Error::kCommunication:
      return tools::kExitCommunication;
    default:
      return tools::kExitFailed;
  }
}

const Command* FindCommand(const std::vector<std::string>& words, std::size_t* consumed) {
  const Command* best = nullptr;
  std::size_t best_words = 0;
  for (const Command* c : Commands()) {
    std::istringstream name(c->name);
    std::vector<std::string> parts;
    for (std::string p; name >> p;) parts.push_back(p);
    if (parts.size() > words.size() || parts.size() <= best_words) continue;
    bool match = true;
    for (std::size_t i = 0; i < parts.size(); ++i) match = match && parts[i] == words[i];
    if (match) {
      best = c;
      best_words = parts.size();
    }
  }
  *consumed = best_words;
  return best;
}

std::string CommandHelp(const Command& c) {
  std::ostringstream s;
  s << "usage: volcomp " << c.name;
  if (*c.arguments != '\0') s << " " << c.arguments;
  if (!c.options.empty()) s << " [options]";
  s << "\n" << c.summary << "\n";
  if (!c.options.empty()) s << "\noptions:\n";
  for (const OptionSpec& o : c.options) {
    s << "  ";
    if (o.alias != nullptr) s << o.alias << ", ";
    s << o.name;
    if (o.value != nullptr) s << " " << o.value;
    s << "\n      " << o.help;
    if (o.unit != nullptr) s << "; unit: " << o.unit;
    if (o.default_value != nullptr) s << "; default: " << o.default_value;
    if (o.repeatable) s << "; repeatable";
    s << "\n";
  }
  if (*c.notes != '\0') s << "\n" << c.notes << "\n";
  s << "\nexit codes: 0 ok, 1 refused or failed, 2 usage, 3 communication\n";
  return s.str();
}

std::string ToolHelp() {
  std::ostringstream s;
  s << "volcomp: volumetric error compensation PC tool\n\n"
       "usage: volcomp COMMAND [options]\n\ncommands:\n";
  for (const Command* c : Commands()) {
    std::string name = c->name;
    name.resize(24, ' ');
    s << "  " << name << c->summary << "\n";
  }
  s << "\n`volcomp help COMMAND` shows a command's options with units and defaults.\n"
       "A word that is a number (-5000) is a value, not an option; `--` ends the options.\n"
       "exit codes: 0 ok, 1 refused or failed (bad input names file and line), 2 usage,\n"
       "3 communication (no board, bus error, timeout)\n";
  return s.str();
}

int RunCommand(const Command& c, const std::vector<std::string>& words, Context& ctx) {
  ctx.json = JsonRequested(c, words);
  Args args(words, &c.options);
  if (!args.status().ok()) return PrintFailure(c, args.status().error(), ctx);
  Expected<Output> output = c.run(args, ctx);
  if (!output.ok()) return PrintFailure(c, output.error(), ctx);
  PrintOutput(*output, ctx);
  return output->exit_code;
}

int RunCommandLine(const std::vector<std::string>& input) {
  Context ctx{std::cin, std::cout, std::cerr};
  std::vector<std::string> words = input;
  if (words.empty() || words[0] == "--help" || words[0] == "-h" ||
      (words[0] == "help" && words.size() == 1)) {
    ctx.out << ToolHelp();
    return words.empty() ? tools::kExitUsage : tools::kExitOk;
  }
  const bool help = words[0] == "help";
  if (help) words.erase(words.begin());
  std::size_t consumed = 0;
  const Command* c = FindCommand(words, &consumed);
  if (c == nullptr) {
    ctx.err << "volcomp: unknown command \"" << words[0] << "\" (try `volcomp help`)\n";
    return tools::kExitUsage;
  }
  bool help_option = false;
  for (std::size_t i = consumed; i < words.size() && words[i] != "--"; ++i) {
    help_option = help_option || words[i] == "--help" || words[i] == "-h";
  }
  if (help || help_option) {
    ctx.out << CommandHelp(*c);
    return tools::kExitOk;
  }
  return RunCommand(
      *c, std::vector<std::string>(words.begin() + static_cast<long>(consumed), words.end()), ctx);
}

}  // namespace volcomp::cli
