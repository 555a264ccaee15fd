// The table of `volcomp-sim` commands, in the order `volcomp-sim help` lists them.
#include "commands.hpp"

namespace volcomp::sim {

const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      NodeCommand(),
      BenchUploadCommand(),
#ifdef VOLCOMP_SIM_HAS_DEMO
      DemoCommand(),
      RunCommand(),
#endif
  };
  return commands;
}

}  // namespace volcomp::sim
