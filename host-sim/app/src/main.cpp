// `volcomp-sim`: the host simulator's program (commands: src/cmd_*.cpp, docs/simulator.md).
#include <iostream>
#include <string>
#include <vector>

#include "volcomp/sim/command_line.hpp"

int main(int argc, char** argv) {
  volcomp::sim::Context ctx{std::cout, std::cerr};
  return volcomp::sim::RunSimCommandLine(std::vector<std::string>(argv + 1, argv + argc), ctx);
}
