// `volcomp`: the PC tool. Dispatches `volcomp COMMAND [SUBCOMMAND] [options]` to the command table.
#include <iostream>
#include <string>
#include <vector>

#include "command.hpp"
#include "version.hpp"

int main(int argc, char** argv) {
  const std::vector<std::string> words(argv + 1, argv + argc);
  if (words.size() == 1 && words[0] == "--version") {
    std::cout << "volcomp " << volcomp::cli::ToolVersion() << "\n";
    return volcomp::tools::kExitOk;
  }
  return volcomp::cli::RunCommandLine(words);
}
