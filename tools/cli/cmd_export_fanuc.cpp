// `volcomp export fanuc`: a FANUC pitch error compensation entry sheet from positioning tests
// (exporters/fanuc_pitch.hpp): parameters 3620–3627 and the increment of every point, for entry
// on the control's screens (the punch-file block syntax of pitch data is not confirmed).
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "export_axes.hpp"
#include "positioning_input.hpp"
#include "volcomp/exporters/fanuc_pitch.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

// The JSON's keys of lengths end in the machine's unit: "p3624_mm" or "p3624_in".
std::string Key(const char* name, const std::string& unit) { return name + ("_" + unit); }

void FanucText(const JsonValue& d, std::ostream& out) {
  const std::string& u = d.get("unit")->string;
  out << "volcomp export fanuc: entry sheet (not a punch file), wrote " << d.get("output")->string
      << "\n  1 count = " << d.get(Key("count", u))->number << " " << u << " (detection unit "
      << d.get(Key("detection_unit", u))->number << " " << u << " x magnification "
      << d.get("magnification")->integer << ")\n";
  for (const JsonValue& a : d.get("axes")->array) {
    out << ErrorTableText(a) << "    3620 = " << a.get("p3620")->integer
        << ", 3621 = " << a.get("p3621")->integer << ", 3622 = " << a.get("p3622")->integer
        << ", 3624 = " << a.get(Key("p3624", u))->number << " " << u << ", largest increment "
        << a.get("largest_increment")->integer << " counts";
    if (const JsonValue* p = a.get("p3626")) {
      out << ", 3626 = " << p->integer << ", 3627 = " << a.get("p3627")->integer;
    }
    out << "\n";
  }
}

// One row per point: number, from, to (machine units), increment, total (counts): the
// "point_columns".
JsonValue PointsJson(const std::vector<exporters::FanucPoint>& points) {
  JsonValue rows = JsonValue::Array();
  for (const exporters::FanucPoint& p : points) {
    rows.Push(JsonValue::Numbers({static_cast<double>(p.number), p.from, p.to,
                                  static_cast<double>(p.increment), static_cast<double>(p.total)}));
  }
  return rows;
}

Expected<Output> RunExportFanuc(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(std::vector<AxisInput> inputs, PositioningInputs(args, /*model_axes=*/true));
  const std::string out_file = args.Required("-o", "--output");
  exporters::FanucOptions o;
  const std::optional<double> detection_unit = args.Number("--detection-unit");
  const long long magnification = args.Integer("--magnification").value_or(1);
  VOLCOMP_TRY_ASSIGN(const ControllerTableArgs table_args, ReadControllerTableArgs(args));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY(LoadModels(&inputs, ctx));
  o.unit = table_args.unit;
  const bool inch = o.unit == exporters::LengthUnit::kInch;
  const std::string u = exporters::UnitName(o.unit, false);
  o.detection_unit = detection_unit.value_or(inch ? 0.0001 : 0.001);
  if (!(o.detection_unit > 0)) return UsageFailure("--detection-unit must be > 0 " + u);
  if (magnification < 1 || magnification > 1000000) {
    return UsageFailure("--magnification " + std::to_string(magnification) + ": at least 1");
  }
  o.magnification = static_cast<int>(magnification);

  Output output;
  std::vector<exporters::FanucAxis> axes;
  std::vector<AxisErrorTable> tables;
  for (const AxisInput& in : inputs) {
    VOLCOMP_TRY_ASSIGN(const AxisErrorTable t,
                       LoadAxisErrorTable(in, table_args, ctx, /*reference_at_first=*/true));
    const std::string warning = UncoveredWarning(t);
    if (!warning.empty()) output.warnings.push_back(warning);
    axes.push_back({in.axis, in.path, t.table});
    tables.push_back(t);
  }
  const Expected<exporters::FanucSheet> sheet = exporters::BuildFanucSheet(axes, o);
  if (!sheet.ok()) return Fail(Error::kInputInvalid, sheet.error().message);
  VOLCOMP_TRY(tools::WriteTextFile(out_file, sheet->text));
  JsonValue axes_json = JsonValue::Array();
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const exporters::FanucAxisSheet& s = sheet->axes[i];
    int largest = 0;
    for (const auto* points : {&s.forward, &s.reverse}) {
      for (const exporters::FanucPoint& p : *points)
        largest = std::max(largest, std::abs(p.increment));
    }
    JsonValue j = ErrorTableJson(tables[i]);
    j.Set("p3620", s.reference_point)
        .Set("p3621", s.most_negative)
        .Set("p3622", s.most_positive)
        .Set("p3623", o.magnification)
        .Set(Key("p3624", u), s.interval)
        .Set("largest_increment", largest)
        .Set("forward", PointsJson(s.forward));
    if (s.bidirectional) {
      j.Set("p3605_bit0", 1)
          .Set("p3626", s.negative_block)
          .Set("p3627", s.reference_opposite)
          .Set("reverse", PointsJson(s.reverse));
    }
    axes_json.Push(std::move(j));
  }
  output.data = JsonValue::Object();
  output.data.Set("output", out_file)
      .Set("unit", u)
      .Set(Key("detection_unit", u), o.detection_unit)
      .Set("magnification", o.magnification)
      .Set(Key("count", u), o.detection_unit * o.magnification)
      .Set("last_point", sheet->last_point)
      .Set("point_columns", JsonValue::Array()
                                .Push("number")
                                .Push(Key("from", u))
                                .Push(Key("to", u))
                                .Push("increment")
                                .Push("total"))
      .Set("axes", std::move(axes_json));
  output.text = FanucText;
  return output;
}

}  // namespace

const Command& ExportFanucCommand() {
  static const Command kCommand{
      "export fanuc",
      "FANUC pitch error compensation entry sheet (3620-3627, increments) from positioning tests",
      "",
      Join({PositioningFileOptions(),
            {ModelAxesOption(),
             {"--output", "-o", "FILE", nullptr, nullptr, "the entry sheet to write (required)"},
             {"--detection-unit", nullptr, "U", "mm or in (--units)", nullptr,
              "the axis's detection unit (default: 0.001 mm; 0.0001 in on an inch machine)"},
             {"--magnification", nullptr, "N", nullptr, "1",
              "parameter 3623: one count is the detection unit times N"}},
            ControllerTableOptions(
                "resample the test to this equal spacing, 3624 (default: the test's positions, "
                "which must then be equally spaced)",
                "the reference position, a compensation point (3620; default: the first)"),
            AllowFewRuns(),
            PositioningFormatOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportFanuc,
      "Each FILE is either the raw readings `evaluate positioning` reads (the mean per\n"
      "target and direction is used) or the mean deviations (position_mm, dev_forward_um\n"
      "[, dev_reverse_um]). Values: corrections, -(actual - nominal), as increments per point\n"
      "in counts; the sign is not confirmed in FANUC's own words (--negate flips it). The\n"
      "axes take consecutive data numbers from 0. See docs/pc-tool.md, \"Controller tables\"."};
  return kCommand;
}

}  // namespace volcomp::cli
