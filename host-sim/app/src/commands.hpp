// The commands of `volcomp-sim` (one cmd_*.cpp each), for the table in commands.cpp.
#pragma once

#include "volcomp/sim/command_line.hpp"

namespace volcomp::sim {

const Command& NodeCommand();
const Command& BenchUploadCommand();
#ifdef VOLCOMP_SIM_HAS_DEMO
const Command& DemoCommand();
const Command& RunCommand();
#endif

}  // namespace volcomp::sim
