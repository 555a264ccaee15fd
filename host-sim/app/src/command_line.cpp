// `volcomp-sim`: help, dispatch, and the one place failures become messages and exit codes.
#include "volcomp/sim/command_line.hpp"

namespace volcomp::sim {
namespace {

void PrintUsage(std::ostream& out) {
  out << "usage: volcomp-sim COMMAND [options]\n\n";
  for (const Command& c : Commands()) out << c.usage;
}

}  // namespace

int RunSimCommandLine(const std::vector<std::string>& words, Context& ctx) {
  if (words.empty() || words[0] == "--help" || words[0] == "help") {
    PrintUsage(ctx.out);
    return words.empty() ? 2 : 0;
  }
  for (const Command& c : Commands()) {
    if (words[0] != c.name) continue;
    args::Args args(std::vector<std::string>(words.begin() + 1, words.end()));
    const Expected<int> code = c.run(args, ctx);
    if (code.ok()) return *code;
    ctx.err << "volcomp-sim " << c.name << ": " << code.error().message << "\n";
    return code.error().code == Error::kUsage ? 2 : 1;
  }
  ctx.err << "volcomp-sim: unknown command \"" << words[0] << "\"\n";
  PrintUsage(ctx.out);
  return 2;
}

}  // namespace volcomp::sim
