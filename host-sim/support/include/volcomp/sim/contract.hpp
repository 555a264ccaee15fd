// Preconditions of the simulator's APIs that only code can break: callers check what a user gives
// them (the command line, a model file) and return a Failure; what reaches these checks is a
// programming error. A broken one stops the process with the reason, in every build, instead of
// dividing by zero later.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace volcomp::sim {

[[noreturn]] inline void PreconditionBroken(const char* what, const char* file, int line) {
  std::fprintf(stderr, "volcomp-sim: %s:%d: precondition broken: %s\n", file, line, what);
  std::abort();
}

}  // namespace volcomp::sim

/// Stops the process with `what` unless `condition` holds.
#define VOLCOMP_SIM_EXPECT(condition, what)                                         \
  do {                                                                              \
    if (!(condition)) ::volcomp::sim::PreconditionBroken(what, __FILE__, __LINE__); \
  } while (0)
