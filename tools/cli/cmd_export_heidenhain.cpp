// `volcomp export heidenhain`: HEIDENHAIN TNC nonlinear axis-error compensation tables from
// positioning tests (exporters/heidenhain_comp.hpp): AXIS_X.COM ... with the BACKLASH column, the
// .CMA configuration table naming them, and NOTES.TXT with the sign rule and its sources (TNC
// tables have no comment line).
#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "commands.hpp"
#include "export_axes.hpp"
#include "positioning_input.hpp"
#include "volcomp/exporters/heidenhain_comp.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

void HeidenhainText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export heidenhain (" << d.get("control")->string << "): wrote into "
      << d.get("output")->string << "\n";
  for (const JsonValue& a : d.get("axes")->array) {
    out << ErrorTableText(a) << "    " << a.get("file")->string << ": largest value "
        << a.get("largest_mm")->number << " mm, largest BACKLASH "
        << a.get("largest_backlash_mm")->number << " mm\n";
  }
  out << "  " << d.get("cma")->string << ": names the .COM files, line 0 active\n  "
      << d.get("notes_file")->string
      << ": the sign rule (error, actual - nominal, unconfirmed on a machine) and sources\n";
}

// Why `--units in` is refused (the tables are metric on every TNC).
constexpr const char* kMetricOnly =
    "a TNC's .COM compensation tables are in mm on an inch machine too: the TNC's machine "
    "configuration is metric, inch is a display and program unit";

Expected<Output> RunExportHeidenhain(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(std::vector<AxisInput> inputs, PositioningInputs(args, /*model_axes=*/true));
  const std::string out_dir = args.Required("-o", "--output");
  const std::string control = args.Value("--control").value_or("tnc6xx");
  const std::string cma = args.Value("--cma").value_or("CONFIG.CMA");
  VOLCOMP_TRY_ASSIGN(const ControllerTableArgs table_args,
                     ReadControllerTableArgs(args, kMetricOnly));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY(LoadModels(&inputs, ctx));
  if (control != "tnc6xx" && control != "tnc4xx") {
    return UsageFailure("--control " + control + ": tnc6xx or tnc4xx");
  }
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) return Fail(Error::kIoError, out_dir + ": cannot create the directory: " + ec.message());

  Output output;
  std::vector<exporters::HeidenhainAxis> axes;
  std::vector<exporters::HeidenhainTable> tables;
  std::vector<char> names;
  std::vector<std::string> files;
  JsonValue axes_json = JsonValue::Array();
  for (const AxisInput& in : inputs) {
    VOLCOMP_TRY_ASSIGN(const AxisErrorTable t, LoadAxisErrorTable(in, table_args, ctx));
    const std::string warning = UncoveredWarning(t);
    if (!warning.empty()) output.warnings.push_back(warning);
    exporters::HeidenhainAxis axis{in.axis, in.path, t.table};
    const Expected<exporters::HeidenhainTable> com = exporters::BuildHeidenhainCom(
        axis, control == "tnc4xx" ? exporters::HeidenhainControl::kTnc4xx
                                  : exporters::HeidenhainControl::kTnc6xx);
    if (!com.ok()) return Fail(Error::kInputInvalid, in.path + ": " + com.error().message);
    axes.push_back(axis);
    tables.push_back(*com);
    names.push_back(in.axis);
    files.push_back(com->file_name);
    axes_json.Push(ErrorTableJson(t)
                       .Set("file", com->file_name)
                       .Set("largest_mm", com->largest_mm)
                       .Set("largest_backlash_mm", com->largest_backlash_mm));
  }
  const std::filesystem::path dir(out_dir);
  for (const exporters::HeidenhainTable& t : tables) {
    VOLCOMP_TRY(tools::WriteTextFile((dir / t.file_name).string(), t.text));
  }
  VOLCOMP_TRY(
      tools::WriteTextFile((dir / cma).string(), exporters::HeidenhainCma(cma, names, files)));
  const std::string notes = (dir / "NOTES.TXT").string();
  VOLCOMP_TRY(tools::WriteTextFile(notes, exporters::HeidenhainNotes(axes, tables, cma)));
  output.data = JsonValue::Object();
  output.data.Set("control", control)
      .Set("output", out_dir)
      .Set("axes", std::move(axes_json))
      .Set("cma", cma)
      .Set("notes_file", notes);
  output.text = HeidenhainText;
  return output;
}

}  // namespace

const Command& ExportHeidenhainCommand() {
  static const Command kCommand{
      "export heidenhain",
      "HEIDENHAIN TNC .COM tables (with BACKLASH) and the .CMA naming them, from positioning tests",
      "",
      Join({PositioningFileOptions(),
            {ModelAxesOption(),
             {"--output", "-o", "DIR", nullptr, nullptr,
              "directory for AXIS_X.COM ..., the .CMA and NOTES.TXT (required)"},
             {"--control", nullptr, "tnc6xx|tnc4xx", nullptr, "tnc6xx",
              "tnc6xx: TNC 640 / MANUALplus 620 (any positions); tnc4xx: TNC 407/415/425 (a "
              "power-of-two spacing times 0.1 um, at most 256 points)"},
             {"--cma", nullptr, "NAME", nullptr, "CONFIG.CMA", "file name of the .CMA table"}},
            ControllerTableOptions(
                "resample the test to this equal spacing (default: the test's own positions)",
                "position where the table is 0 (default: not zeroed)", kMetricOnly),
            AllowFewRuns(),
            PositioningFormatOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportHeidenhain,
      "Each FILE is either the raw readings `evaluate positioning` reads (the mean per\n"
      "target and direction is used) or the mean deviations (position_mm, dev_forward_um\n"
      "[, dev_reverse_um]). Values: the measured error, actual - nominal, in mm; BACKLASH the\n"
      "extra error moving negative. The sign is not confirmed on a machine (--negate flips\n"
      "it). See docs/pc-tool.md, \"Controller tables\"."};
  return kCommand;
}

}  // namespace volcomp::cli
