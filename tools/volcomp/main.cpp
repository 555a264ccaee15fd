// `volcomp`: the PC tool. Dispatches `volcomp COMMAND [SUBCOMMAND] [options]` to the command table.
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "volcomp/tools/csv.hpp"

namespace {

using volcomp::tools::Command;
using volcomp::tools::Commands;

void PrintHelp() {
  std::cout << "volcomp: volumetric error compensation PC tool\n\n"
               "usage: volcomp COMMAND [options]\n\ncommands:\n";
  for (const Command& c : Commands()) {
    std::string name = c.name;
    name.resize(24, ' ');
    std::cout << "  " << name << c.summary << "\n";
  }
  std::cout << "\n`volcomp help COMMAND` shows a command's options.\n";
}

// Longest command whose words match the start of `words`; sets *consumed to the word count.
const Command* FindCommand(const std::vector<std::string>& words, std::size_t* consumed) {
  const Command* best = nullptr;
  std::size_t best_words = 0;
  for (const Command& c : Commands()) {
    std::vector<std::string> parts;
    std::string part;
    for (const char* p = c.name;; ++p) {
      if (*p == ' ' || *p == '\0') {
        parts.push_back(part);
        part.clear();
        if (*p == '\0') break;
      } else {
        part += *p;
      }
    }
    if (parts.size() > words.size() || parts.size() <= best_words) continue;
    bool match = true;
    for (std::size_t i = 0; i < parts.size(); ++i) match = match && parts[i] == words[i];
    if (match) {
      best = &c;
      best_words = parts.size();
    }
  }
  *consumed = best_words;
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty() || words[0] == "--help" || words[0] == "-h" ||
      (words[0] == "help" && words.size() == 1)) {
    PrintHelp();
    return words.empty() ? 2 : 0;
  }
  if (words[0] == "--version") {
    std::cout << "volcomp " << VOLCOMP_VERSION << "\n";
    return 0;
  }
  const bool help = words[0] == "help";
  if (help) words.erase(words.begin());
  std::size_t consumed = 0;
  const Command* cmd = FindCommand(words, &consumed);
  if (cmd == nullptr) {
    std::cerr << "volcomp: unknown command \"" << words[0] << "\" (try `volcomp help`)\n";
    return 2;
  }
  if (help ||
      (words.size() > consumed && (words[consumed] == "--help" || words[consumed] == "-h"))) {
    std::cout << "usage: volcomp " << cmd->name << " " << cmd->usage << "\n";
    return 0;
  }
  volcomp::tools::Args args(std::vector<std::string>(words.begin() + consumed, words.end()));
  try {
    return cmd->run(args);
  } catch (const volcomp::tools::UsageError& e) {
    std::cerr << "volcomp " << cmd->name << ": " << e.what() << "\nusage: volcomp " << cmd->name
              << " " << cmd->usage << "\n";
    return 2;
  } catch (const volcomp::tools::InputError& e) {
    std::cerr << "volcomp " << cmd->name << ": error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "volcomp " << cmd->name << ": error: " << e.what() << "\n";
    return 1;
  }
}
