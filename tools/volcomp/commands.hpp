// The `volcomp` PC tool's command table: each command is `int Run(Args&)` in its own file, with
// its options declared once in commands.cpp (name, value, unit, default, help). The same rows
// drive the parser (tools::Args) and `volcomp help COMMAND`.
//
// To add a command: write `int RunFoo(tools::Args& args)` in cmd_foo.cpp, declare it here and add
// one entry with its options to the table in commands.cpp. Commands write results to stdout,
// diagnostics to stderr, and return or throw as volcomp/tools/exit_codes.hpp says (0 ok,
// 1 refused/failed, 2 usage, 3 communication).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "volcomp/tools/args.hpp"
#include "volcomp/tools/exit_codes.hpp"

namespace volcomp::tools {

struct Command {
  const char* name;       // one or two words, e.g. "build grid"
  const char* summary;    // one line for `volcomp help`
  const char* arguments;  // positional arguments for the usage line ("FILE|-"), "" for none
  std::vector<OptionSpec> options;
  int (*run)(Args& args);
  const char* notes = "";  // extra help text (option groups, examples)
};

const std::vector<Command>& Commands();

/// The command named by the first words of `words` (longest match); sets *consumed to the number
/// of words of its name. nullptr when none matches.
const Command* FindCommand(const std::vector<std::string>& words, std::size_t* consumed);

/// The command whose run function is `run` (for in-process tests); nullptr when none.
const Command* FindCommand(int (*run)(Args&));

/// `volcomp help COMMAND`: usage line, summary, every option with its value, unit, default and
/// meaning, and the notes.
std::string CommandHelp(const Command& command);

/// `volcomp help`: the command list and the exit codes.
std::string ToolHelp();

/// Runs `volcomp WORDS...` as main() does: help, dispatch with the command's option table, and
/// the mapping of exceptions to exit codes. Diagnostics go to std::cerr, results to std::cout.
int RunCommandLine(const std::vector<std::string>& words);

/// Runs one command with its option table (the part of RunCommandLine after dispatch).
int RunCommand(const Command& command, const std::vector<std::string>& args);

int RunBuildGrid(Args& args);
int RunInspect(Args& args);
int RunLookup(Args& args);
int RunUpload(Args& args);
int RunVerify(Args& args);
int RunActivate(Args& args);
int RunDeactivate(Args& args);
int RunReference(Args& args);
int RunStatus(Args& args);
int RunMonitor(Args& args);
int RunSdo(Args& args);
int RunEds(Args& args);
// Board configuration and NMT: cmd_config.cpp.
int RunConfigShow(Args& args);
int RunConfigSave(Args& args);
int RunConfigApply(Args& args);
int RunNmt(Args& args);
// Metrology: cmd_evaluate_*.cpp, cmd_program.cpp, cmd_report_compare.cpp.
int RunEvaluatePositioning(Args& args);
int RunEvaluateDiagonal(Args& args);
int RunEvaluateRotary(Args& args);
int RunProgramPositioning(Args& args);
int RunProgramDiagonal(Args& args);
int RunReportCompare(Args& args);
// Table builders: cmd_build_model/tracker/kmtpp/axis.cpp, cmd_model_eval.cpp.
int RunBuildModel(Args& args);
int RunBuildTracker(Args& args);
int RunBuildKmtpp(Args& args);
int RunBuildAxis(Args& args);
int RunModelEval(Args& args);
int RunExportLinuxcnc(Args& args);

}  // namespace volcomp::tools
