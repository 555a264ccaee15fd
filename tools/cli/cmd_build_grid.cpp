// `volcomp build grid`: a GRID3 image from corrections given at the nodes of a regular lattice
// (CSV; the format is in volcomp/builders/node_grid.hpp). Nothing on stdout; the file written is
// named on stderr.
#include <ostream>
#include <string>
#include <vector>

#include "board_fit.hpp"
#include "build_options.hpp"
#include "commands.hpp"
#include "option_groups.hpp"
#include "volcomp/builders/node_grid.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

Expected<Output> RunBuildGrid(Args& args, Context& ctx) {
  const std::string csv_path = args.Required("--csv");
  const std::string out_path = args.Required("-o", "--output");
  VOLCOMP_TRY(args.status());
  VOLCOMP_TRY_ASSIGN(const std::vector<char> names,
                     image::ParseAxisList(args.Value("--axes").value_or("X,Y,Z"), "--axes"));
  if (names.size() != 3) return UsageFailure("--axes: GRID3 needs exactly three axes");
  image::ImageRequest req;
  VOLCOMP_TRY_ASSIGN(req.axes, ParseAxisResolutions(args, names));
  VOLCOMP_TRY(ParseImageOptions(args, &req));
  VOLCOMP_TRY_ASSIGN(const std::optional<BoardFileCheck> board, ParseBoardFileCheck(args));
  VOLCOMP_TRY(args.Finish());

  VOLCOMP_TRY_ASSIGN(const tools::CsvTable csv, tools::CsvTable::ReadFile(csv_path));
  VOLCOMP_TRY_ASSIGN(req.grid, builders::NodeGridFromCsv(csv, req.axes));
  req.info.emplace("source", csv_path);
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> image, image::BuildImage(req));
  Output output;
  if (board) {
    JsonValue check;
    VOLCOMP_TRY(CheckImageAgainstBoardFile(*board, image, &output.warnings, &check));
  }
  VOLCOMP_TRY(tools::WriteFileBytes(out_path, image));
  const auto& lattice = req.grid->lattice;
  ctx.err << "wrote " << out_path << ": " << image.size() << " bytes, " << lattice[0].nodes << "x"
          << lattice[1].nodes << "x" << lattice[2].nodes << " nodes\n";
  return output;
}

}  // namespace

const Command& BuildGridCommand() {
  static const Command kCommand{
      "build grid", "build a table image from corrections at grid nodes (CSV)", "",
      Join({{{"--csv", nullptr, "FILE", nullptr, nullptr,
              "corrections at the nodes (required): x_mm|x_steps ..., dx_um|dx_steps ..."},
             {"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"},
             {"--axes", nullptr, "X,Y,Z", nullptr, "X,Y,Z", "the three grid axes"}},
            ResolutionOptions(),
            ImageOptions(),
            BoardFileOptions()}),
      RunBuildGrid};
  return kCommand;
}

}  // namespace volcomp::cli
