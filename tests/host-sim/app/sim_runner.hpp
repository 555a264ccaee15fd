// `volcomp-sim` run in process for the command tests: the exit code and what it printed.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "volcomp/sim/command_line.hpp"

namespace volcomp::sim {

struct SimRun {
  int code = -1;
  std::string out, err;
};

inline SimRun Sim(const std::vector<std::string>& words) {
  std::ostringstream out, err;
  Context ctx{out, err};
  SimRun r;
  r.code = RunSimCommandLine(words, ctx);
  r.out = out.str();
  r.err = err.str();
  return r;
}

}  // namespace volcomp::sim
