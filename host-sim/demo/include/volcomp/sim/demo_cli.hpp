// `volcomp-sim demo [--seed N] [--report DIR] [--model s500|CONFIG] [--points N] [--quick]
//                   [--laser-noise-um S] [--tracker-noise-um S]`:
// option parsing, the run, the summary and the report. Returns the exit code: 0 when every check
// passed, 1 when one failed or the run stopped, 2 for bad options.
#pragma once

#include <string>
#include <vector>

namespace volcomp::sim {

int RunDemoCommand(const std::vector<std::string>& args);

/// Usage lines of the demo command (for `volcomp-sim help`).
const char* DemoUsage();

}  // namespace volcomp::sim
