// `volcomp eds [-o FILE]`: the node's EDS (CiA 306) generated from the object dictionary
// (canopen_client/eds_writer.hpp); docs/volcomp.eds is this output.
#include <sstream>

#include "commands.hpp"
#include "volcomp/canopen_client/eds_writer.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

Expected<Output> RunEds(Args& args, Context& ctx) {
  const std::string path = args.Value("--output", "-o").value_or("-");
  VOLCOMP_TRY(args.Finish());
  if (path == "-") {
    canopen_client::WriteEds(ctx.out);
    return Output{};
  }
  std::ostringstream eds;
  canopen_client::WriteEds(eds);
  if (!tools::WriteTextFile(path, eds.str()).ok()) {
    return Fail(Error::kIoError, path + ": cannot write");
  }
  return Output{};
}

}  // namespace

const Command& EdsCommand() {
  static const Command kCommand{
      "eds",
      "write the node's EDS file (CiA 306) generated from the object dictionary",
      "",
      {{"--output", "-o", "FILE", nullptr, "-", "file to write (- = stdout)"}},
      RunEds};
  return kCommand;
}

}  // namespace volcomp::cli
