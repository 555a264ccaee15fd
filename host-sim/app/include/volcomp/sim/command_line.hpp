// The command layer of `volcomp-sim`: each command (src/cmd_*.cpp) declares its usage beside
// itself, parses its options with args::Args (the non-throwing API), calls the simulator's
// libraries, which return results, and prints as it goes on Context::out / err. It returns the
// exit code of a run that completed (0, or 1 when a check failed) or a Failure, which
// RunSimCommandLine prints as "volcomp-sim COMMAND: MESSAGE" and maps to the exit code: 2 for
// kUsage (bad options), 1 for anything else. No library under host-sim knows the command line.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "volcomp/args/args.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

/// Where a command writes (std::cout / std::cerr in the program; string streams in tests).
struct Context {
  std::ostream& out;
  std::ostream& err;
};

struct Command {
  const char* name;
  const char* usage;  // its lines of `volcomp-sim help`
  Expected<int> (*run)(args::Args& args, Context& ctx);
};

/// A usage failure (exit code 2).
inline Unexpected<Failure> UsageFailure(std::string message) {
  return Fail(Error::kUsage, std::move(message));
}

/// The commands of this build, in the order `volcomp-sim help` lists them (the demo only when
/// the PC tool's libraries were built).
const std::vector<Command>& Commands();

/// `volcomp-sim WORDS...` as main() runs it: help, dispatch, failure messages; the exit code.
int RunSimCommandLine(const std::vector<std::string>& words, Context& ctx);

}  // namespace volcomp::sim
