// The `volcomp` PC tool's command table: each command is `int Run(Args&)` in its own file.
//
// To add a command: write `int RunFoo(tools::Args& args)` in cmd_foo.cpp, declare it here, add one
// line to kCommands in commands.cpp and the file to tools/CMakeLists.txt. Commands write results to
// stdout, diagnostics to stderr, and return the process exit code (0 ok, 1 failure, 2 usage).
#pragma once

#include <vector>

#include "volcomp/tools/args.hpp"

namespace volcomp::tools {

struct Command {
  const char* name;     // one or two words, e.g. "build grid"
  const char* summary;  // one line for `volcomp help`
  const char* usage;    // full usage text for `volcomp help NAME`
  int (*run)(Args& args);
};

const std::vector<Command>& Commands();

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
// Metrology (issue 4): cmd_evaluate_*.cpp, cmd_program.cpp.
int RunEvaluatePositioning(Args& args);
int RunEvaluateDiagonal(Args& args);
int RunEvaluateRotary(Args& args);
int RunProgramPositioning(Args& args);
int RunProgramDiagonal(Args& args);
// Table builders (issue 5): cmd_build_model/tracker/kmtpp/axis.cpp, cmd_model_eval.cpp.
int RunBuildModel(Args& args);
int RunBuildTracker(Args& args);
int RunBuildKmtpp(Args& args);
int RunBuildAxis(Args& args);
int RunModelEval(Args& args);
int RunExportLinuxcnc(Args& args);

}  // namespace volcomp::tools
