// Exit codes of the command layers (`volcomp`, `volcomp-sim`), documented in docs/pc-tool.md:
//
//   0  ok: the command did what was asked;
//   1  refused or failed: bad input data (the message names file, line and problem), a check
//      that failed, a request the board refused;
//   2  usage: unknown command or option, missing or malformed option value;
//   3  communication: no board or adapter, bus error, timeout.
//
// A failure's error code decides its exit code, in one place: cli::ExitCodeOf (kUsage 2,
// kCommunication 3, anything else 1).
#pragma once

namespace volcomp::tools {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitCommunication = 3;

}  // namespace volcomp::tools
