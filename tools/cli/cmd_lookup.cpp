// `volcomp lookup IMAGE`: the table's correction at points read as CSV (stdin, or --points FILE),
// computed by the firmware's lookup code and written as CSV on stdout as the rows are read
// (columns: volcomp/image/point_lookup.hpp).
#include <ostream>

#include "commands.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/image/point_lookup.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::cli {
namespace {

Expected<Output> RunLookup(Args& args, Context& ctx) {
  const auto points_path = args.Value("--points");
  const auto pos = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (pos.size() != 1) return UsageFailure("expected one IMAGE file");
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage img, image::ReadImageFile(pos[0]));
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable csv, points_path
                                                    ? tools::CsvTable::ReadFile(*points_path)
                                                    : tools::CsvTable::Read(ctx.in, "<stdin>"));
  VOLCOMP_TRY_ASSIGN(const image::PointLookup lookup, image::PointLookup::Create(img, csv));
  ctx.out << lookup.Header();
  for (const tools::CsvRow& row : csv.rows()) {
    VOLCOMP_TRY_ASSIGN(const std::string line, lookup.Row(row));
    ctx.out << line;
  }
  return Output{};
}

}  // namespace

const Command& LookupCommand() {
  static const Command kCommand{
      "lookup",
      "correction at points read as CSV, written as CSV on stdout",
      "IMAGE",
      {{"--points", nullptr, "FILE", nullptr, nullptr,
        "points CSV: x_mm|x_steps ..., optional dir_x (default: standard input)"}},
      RunLookup};
  return kCommand;
}

}  // namespace volcomp::cli
