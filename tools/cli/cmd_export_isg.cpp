// `volcomp export isg`: ISG kernel / Beckhoff TwinCAT CNC leadscrew error compensation lists
// (LSEC/SSFK, exporters/isg_lsec.hpp) from positioning test results, read as `export linuxcnc`
// reads them: one achskw_<axis>.lis per axis into the output directory.
#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "export_axes.hpp"
#include "option_groups.hpp"
#include "positioning_input.hpp"
#include "volcomp/datasets/positioning_csv.hpp"
#include "volcomp/exporters/isg_lsec.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

std::vector<std::string> FileHeader(char axis,
                                    const std::string& source,
                                    bool rotary,
                                    bool negate) {
  return {
      "volcomp export isg: leadscrew error compensation list (LSEC/SSFK) of axis " +
          std::string(1, axis),
      "from " + source + " (positioning test, mean deviation per position and direction)",
      std::string("sign: the values are the error, actual - setpoint") +
          (negate ? ", NEGATED on request (--negate)" : ", no sign changed"),
      "  (\"absolute position errors\": https://infosys.beckhoff.com/content/1033/"
      "tf5200_axis_compensation_parameters/113439115.html)",
      std::string("units: setpoints and values in ") + (rotary ? "0.0001 deg" : "0.1 um") +
          " (P-COMP-00019/23/24; kw.ssfk.unit 1 as in the manual's example)",
  };
}

void ExportIsgText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export isg (leadscrew error compensation lists)\n";
  for (const JsonValue& a : d.get("axes")->array) {
    out << "  axis " << a.get("axis")->string << " (kopf.achs_nr " << a.get("axis_number")->integer
        << "): " << a.get("points")->integer << " points from " << a.get("from")->number << " to "
        << a.get("to")->number << ", "
        << (a.get("bilateral")->boolean ? "bilateral" : "one table for both directions")
        << (a.get("negated")->boolean ? ", negated" : "") << ", largest value "
        << a.get("max_abs_value")->number << " " << a.get("value_unit")->string << ", wrote "
        << a.get("file")->string << "\n";
  }
}

// Why `--units in` is refused: kw.ssfk.unit (P-COMP-00017) knows encoder increments and 0.1 µm.
constexpr const char* kMetricOnly =
    "an ISG LSEC list is in 0.1 um (kw.ssfk.unit, P-COMP-00017: encoder increments or metric; "
    "there is no inch)";

Expected<Output> RunExportIsg(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(std::vector<AxisInput> inputs, PositioningInputs(args, /*model_axes=*/true));
  const std::string out_dir = args.Required("-o", "--output");
  const long long max_points =
      args.Integer("--max-points")
          .value_or(static_cast<long long>(exporters::kIsgLsecDefaultMaxPoints));
  VOLCOMP_TRY(args.status());
  if (max_points < 2) return UsageFailure("--max-points must be at least 2");
  VOLCOMP_TRY(ParseMachineUnits(args, kMetricOnly));
  VOLCOMP_TRY_ASSIGN(auto numbers,
                     ParseAxisNumberMap(args.Value("--axis-numbers"), "--axis-numbers",
                                        "logical axis number", 1, 1, 65535));
  const bool negate = args.Flag("--negate");
  metrology::GroupingOptions grouping;
  grouping.allow_few_approaches = args.Flag("--allow-few-runs");
  VOLCOMP_TRY_ASSIGN(const datasets::PositioningReadOptions read,
                     ParsePositioningReadOptions(args));
  args.Flag("--json");  // the command layer prints the data as JSON
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY(LoadModels(&inputs, ctx));

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) return Fail(Error::kIoError, out_dir + ": cannot create the directory: " + ec.message());
  std::map<int, char> axis_of_number;
  for (const AxisInput& input : inputs) {
    const auto [other, added] = axis_of_number.emplace(numbers[input.axis], input.axis);
    if (!added) {
      return UsageFailure("--axis-numbers: " + std::string(1, other->second) + " and " +
                          std::string(1, input.axis) + " both have the logical axis number " +
                          std::to_string(numbers[input.axis]));
    }
  }
  JsonValue axes = JsonValue::Array();
  for (const AxisInput& in : inputs) {
    const char name = in.axis;
    const std::string& path = in.path;
    VOLCOMP_TRY_ASSIGN(const model::PositioningData data, LoadAxisTest(in, read, grouping, ctx));
    exporters::IsgLsecOptions options;
    options.axis_number = numbers[name];
    options.axis_name = std::string(1, name);
    options.negate = negate;
    options.max_points = static_cast<std::size_t>(max_points);
    const auto list = exporters::BuildIsgLsec(data, options);
    if (!list.ok()) {
      return Fail(Error::kInputInvalid,
                  path + ": axis " + std::string(1, name) + ": " + list.error().message);
    }
    const std::string file =
        "achskw_" + std::string(1, static_cast<char>(name - 'A' + 'a')) + ".lis";
    const std::string full = (std::filesystem::path(out_dir) / file).string();
    VOLCOMP_TRY(tools::WriteTextFile(
        full,
        exporters::FormatIsgLsec(*list, options, FileHeader(name, path, data.rotary, negate))));
    long long largest = 0;
    for (const exporters::IsgLsecRow& r : list->rows) {
      largest = std::max({largest, static_cast<long long>(r.pos < 0 ? -r.pos : r.pos),
                          static_cast<long long>(r.neg < 0 ? -r.neg : r.neg)});
    }
    JsonValue a = JsonValue::Object();
    a.Set("axis", std::string(1, name))
        .Set("axis_number", options.axis_number)
        .Set("source", path)
        .Set("points", uint64_t{list->rows.size()})
        .Set("from", data.position.front())
        .Set("to", data.position.back())
        .Set("bilateral", list->bilateral)
        .Set("negated", negate)
        .Set("max_abs_value", largest)
        .Set("value_unit", data.rotary ? "0.0001 deg" : "0.1 um")
        .Set("file", full);
    axes.Push(std::move(a));
  }
  Output output;
  output.data = JsonValue::Object();
  output.data.Set("output", out_dir).Set("axes", std::move(axes));
  output.text = ExportIsgText;
  return output;
}

}  // namespace

const Command& ExportIsgCommand() {
  static const Command kCommand{
      "export isg",
      "ISG / TwinCAT CNC leadscrew error compensation lists (achskw*.lis) from positioning tests",
      "",
      Join({PositioningFileOptions(),
            {ModelAxesOption(),
             {"--output", "-o", "DIR", nullptr, nullptr,
              "directory for achskw_x.lis ... (required)"},
             {"--axis-numbers", nullptr, "X=N,...", nullptr, nullptr,
              "logical axis number (kopf.achs_nr) per axis (default: X=1 ... W=9)"},
             {"--negate", nullptr, nullptr, nullptr, nullptr,
              "write actual - setpoint negated (for a controller that proves the other way)"},
             {"--max-points", nullptr, "N", nullptr, "1500",
              "the controller's kw.ssfk.max_points (P-COMP-00059): kw_nr_max must be smaller"},
             MachineUnitsOption(kMetricOnly)},
            AllowFewRuns(),
            PositioningFormatOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportIsg,
      PositioningFileNotes()};
  return kCommand;
}

}  // namespace volcomp::cli
