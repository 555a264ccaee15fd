// Exit codes of the PC tool, one definition for every command (documented in docs/pc-tool.md).
//
//   0  ok: the command did what was asked;
//   1  refused or failed: bad input data (the message names file, line and problem), a check
//      that failed, a request the board refused;
//   2  usage: unknown command or option, missing or malformed option value;
//   3  communication: no board or adapter, bus error, timeout.
//
// Commands return these codes or throw: UsageError (args.hpp) → 2, CommunicationError → 3, any
// other exception (InputError of csv.hpp, ...) → 1. The mapping is done once, in
// RunCommandLine (tools/cli/commands.hpp).
#pragma once

#include <stdexcept>

namespace volcomp::tools {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitCommunication = 3;

/// No answer, no adapter, bus error: the board could not be reached (exit code 3).
class CommunicationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace volcomp::tools
