// The command layer of the `volcomp` PC tool: what a command is, what it gets and what it returns.
//
// A command declares its options beside its code (cmd_*.cpp), parses them with Args, calls the
// libraries (which return Expected<T> and never throw) and returns Expected<Output>: the figures it
// reports as one JSON document, and the text layout that reads them. The command layer
// (command_line.cpp) prints the Output, as JSON with --json or through the layout otherwise, so
// the text can show nothing the JSON lacks; it prints a Failure as a message and maps its code to
// the exit code (ExitCodeOf). Streaming commands (monitor, upload's progress) also write to
// Context::out / err as they go.
//
//   Expected<Output> RunInspect(Args& args, Context& ctx) {
//     const bool json = args.Flag("--json");
//     const auto files = args.Positionals();
//     VOLCOMP_TRY(args.Finish());
//     if (files.size() != 1) return UsageFailure("expected one IMAGE file");
//     VOLCOMP_TRY_ASSIGN(const auto image, image::ReadImageFile(files[0]));
//     return Output{InspectData(files[0], image), InspectText};
//   }
//   extern const Command kInspect{"inspect", "summarise a table image", "IMAGE", {...},
//   RunInspect};
#pragma once

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/args/args.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/tools/exit_codes.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::cli {

using args::Args;
using args::OptionSpec;
using tools::JsonValue;

/// Where a command reads and writes (std::cin/cout/cerr in the tool; string streams in tests).
struct Context {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
  bool json = false;  // --json was given (for the commands that declare it)
};

/// How a command's data reads as text; the JSON form is the data itself.
using TextLayout = void (*)(const JsonValue& data, std::ostream& out);

/// What a command reports.
struct Output {
  Output() = default;
  Output(JsonValue d,
         TextLayout layout = nullptr,
         std::vector<std::string> w = {},  // NOLINT
         int code = tools::kExitOk)
      : data(std::move(d)), text(layout), warnings(std::move(w)), exit_code(code) {}

  JsonValue data;                     // every figure the command reports (null: nothing)
  TextLayout text = nullptr;          // its text view (nullptr: nothing on stdout in text mode)
  std::vector<std::string> warnings;  // printed on stderr as "warning: ..." in both modes
  int exit_code = tools::kExitOk;     // a result that is not ok without being an error (verify)
};

using RunFunction = Expected<Output> (*)(Args& args, Context& ctx);

struct Command {
  const char* name;       // one or two words, e.g. "build grid"
  const char* summary;    // one line for `volcomp help`
  const char* arguments;  // positional arguments for the usage line ("FILE|-"), "" for none
  std::vector<OptionSpec> options;
  RunFunction run = nullptr;
  const char* notes = "";  // extra help text (option groups, examples)
};

/// A usage failure (exit code 2): bad or missing options or arguments.
inline Unexpected<Failure> UsageFailure(std::string message) {
  return Fail(Error::kUsage, std::move(message));
}

/// A communication failure (exit code 3): no board, no adapter, bus error, timeout.
inline Unexpected<Failure> CommunicationFailure(std::string message) {
  return Fail(Error::kCommunication, std::move(message));
}

/// The exit code of a failure: kUsage 2, kCommunication 3, anything else 1 (refused or failed).
int ExitCodeOf(const Failure& failure);

/// Every command of the tool, in the order `volcomp help` lists them (commands.cpp).
const std::vector<const Command*>& Commands();

/// The command named by the first words of `words` (longest match); sets *consumed to the number
/// of words of its name. nullptr when none matches.
const Command* FindCommand(const std::vector<std::string>& words, std::size_t* consumed);

/// `volcomp help COMMAND`: usage line, summary, every option with its value, unit, default and
/// meaning, and the notes.
std::string CommandHelp(const Command& command);

/// `volcomp help`: the command list and the exit codes.
std::string ToolHelp();

/// Runs one command with its option table and prints its Output or Failure on `ctx`; returns
/// the exit code.
int RunCommand(const Command& command, const std::vector<std::string>& args, Context& ctx);

/// Runs `volcomp WORDS...` as main() does: help, dispatch, printing, exit code; std::cin, cout
/// and cerr.
int RunCommandLine(const std::vector<std::string>& words);

}  // namespace volcomp::cli
