// `volcomp build image --grid A.vct --axis B.vct -o C.vct`: one image from the GRID3 of one image
// and the AXIS1D tables of another, after checking they belong together (image/image_join.hpp).
// The text view names the file written and its sections.
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "board_fit.hpp"
#include "commands.hpp"
#include "option_groups.hpp"
#include "volcomp/image/image_join.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

std::string Hex32(uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", v);
  return text;
}

void BuildImageText(const JsonValue& d, std::ostream& out) {
  out << "wrote " << d.get("image")->string << ": " << d.get("bytes")->integer
      << " bytes, table id " << d.get("table_id")->integer << ", CRC-32 " << d.get("crc32")->string
      << "; GRID3 from " << d.get("grid_image")->string << ", AXIS1D";
  for (const JsonValue& a : d.get("axis1d_axes")->array) out << " " << a.string;
  out << "\n";
}

Expected<Output> RunBuildImage(Args& args, Context&) {
  const std::string grid_path = args.Required("--grid");
  const std::string axis_path = args.Required("--axis");
  const std::string out_path = args.Required("-o", "--output");
  const auto id = args.Integer("--table-id");
  args.Flag("--json");  // the command layer prints the data as JSON
  image::JoinOptions options;
  for (const std::string& kv : args.Values("--info")) {
    const std::size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) return UsageFailure("--info takes KEY=VALUE");
    options.info[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  VOLCOMP_TRY_ASSIGN(const std::optional<BoardFileCheck> board, ParseBoardFileCheck(args));
  VOLCOMP_TRY(args.Finish());
  if (id) {
    if (*id < 1 || *id > 0xFFFFFFFFll) {
      return UsageFailure("--table-id must be 1..4294967295 (0 means no table active)");
    }
    options.table_id = static_cast<uint32_t>(*id);
  }
  if (grid_path == out_path || axis_path == out_path) {
    return UsageFailure("-o names an input image: write the joined image to a new file");
  }
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage grid, image::ReadImageFile(grid_path));
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage axis, image::ReadImageFile(axis_path));
  VOLCOMP_TRY_ASSIGN(const image::JoinedImage joined,
                     image::JoinImages({grid_path, &grid}, {axis_path, &axis}, options));
  Output output;
  output.warnings = joined.warnings;
  JsonValue board_check;
  if (board) {
    VOLCOMP_TRY(CheckImageAgainstBoardFile(*board, joined.bytes, &output.warnings, &board_check));
  }
  VOLCOMP_TRY(tools::WriteFileBytes(out_path, joined.bytes));
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage result,
                     image::LoadedImage::FromBytes(joined.bytes, out_path));
  const table::TableView& v = result.view();
  JsonValue names = JsonValue::Array();
  for (uint8_t i = 0; i < v.axis1d_count; ++i) {
    names.Push(std::string(1, v.axes[v.axis1d[i].axis].name));
  }
  output.data = JsonValue::Object();
  output.data.Set("image", out_path)
      .Set("bytes", uint64_t{joined.bytes.size()})
      .Set("table_id", uint64_t{v.table_id})
      .Set("crc32", Hex32(v.crc32))
      .Set("grid_image", grid_path)
      .Set("axis_image", axis_path)
      .Set("axis1d_axes", std::move(names));
  if (board) output.data.Set("board_check", std::move(board_check));
  output.text = BuildImageText;
  return output;
}

}  // namespace

const Command& BuildImageCommand() {
  static const Command kCommand{
      "build image",
      "join a GRID3 image and an AXIS1D image (same axes and units per step) into one",
      "",
      Join({{{"--grid", nullptr, "IMAGE", nullptr, nullptr,
              "image with the GRID3 (build grid, build model, ...) (required)"},
             {"--axis", nullptr, "IMAGE", nullptr, nullptr,
              "image with the AXIS1D tables (build axis) (required)"},
             {"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"},
             {"--table-id", nullptr, "N", nullptr, nullptr,
              "id of the joined image, 1..4294967295 (default: the parts' id, which must agree)"},
             {"--info", nullptr, "KEY=VALUE", nullptr, nullptr,
              "text for the image's INFO section (machine, operator, ...)", true},
             {"--json", nullptr, nullptr, nullptr, nullptr,
              "machine-readable build report on stdout"}},
            BoardFileOptions()}),
      RunBuildImage,
      "Every axis of the AXIS1D image must be an axis of the GRID3 image with the same kind and\n"
      "units per step; the joined image keeps the GRID3 image's axes. The tables are copied with\n"
      "their own encoding, so the joined image corrects exactly as its parts."};
  return kCommand;
}

}  // namespace volcomp::cli
