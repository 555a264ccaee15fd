// `volcomp export siemens`: a SINUMERIK compensation program from positioning tests
// (exporters/siemens_comp.hpp): LEC ($AA_ENC_COMP, %_N_AX_EEC_INI) or, for direction-dependent
// tables, CEC ($AN_CEC with $AN_CEC_DIRECTION 1 / −1), and cross-axis CEC tables from straightness
// tests (--cross), with the machine data to set as comments.
#include <cctype>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "export_axes.hpp"
#include "positioning_input.hpp"
#include "volcomp/exporters/siemens_comp.hpp"
#include "volcomp/exporters/straightness.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

void SiemensText(const JsonValue& d, std::ostream& out) {
  out << "volcomp export siemens: " << d.get("mode")->string << " program, wrote "
      << d.get("output")->string << "\n";
  for (const JsonValue& a : d.get("axes")->array) {
    out << ErrorTableText(a);
  }
  for (const JsonValue& t : d.get("tables")->array) {
    out << "  " << t.get("machine_axis")->string;
    if (t.get("output_axis")->string != t.get("machine_axis")->string) {
      out << " -> " << t.get("output_axis")->string;
    }
    if (t.get("cec_table")->integer >= 0) {
      const long long dir = t.get("direction")->integer;
      out << ": CEC table " << t.get("cec_table")->integer
          << (dir > 0   ? " (positive traverse)"
              : dir < 0 ? " (negative traverse)"
                        : " (both directions)");
    } else {
      out << ": LEC, encoder " << d.get("encoder")->integer;
    }
    out << ", " << t.get("points")->integer << " points, " << t.get("min")->number << " to "
        << t.get("max")->number << " step " << t.get("step")->number << ", largest value "
        << t.get("largest_value")->number << " " << t.get("unit")->string << "\n";
  }
  out << "points per table at most " << d.get("max_points")->integer
      << " (--max-points: the machine's "
      << (d.get("mode")->string == "LEC" ? "MD38000" : "MD18342")
      << "); the machine data to set are at the top of the program\n";
}

Expected<std::map<char, std::string>> MachineAxisNames(const std::optional<std::string>& text) {
  std::map<char, std::string> names;
  if (!text) return names;
  VOLCOMP_TRY_ASSIGN(const auto assignments, image::ParseAxisAssignments(*text, "--names"));
  for (const auto& [axis, name] : assignments) {
    bool ok = !name.empty();
    for (const char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ok) {
      return UsageFailure(
          "--names: " + std::string(1, axis) + "=" + name +
          ": a SINUMERIK machine axis name is letters, digits and _ (e.g. X1, AX1)");
    }
    names[axis] = name;
  }
  return names;
}

// One `--cross IN:OUT=FILE`: a straightness test of the output axis over the input axis.
struct CrossInput {
  AxisInput input;  // the input axis and the file
  char output = 'Y';
};

// `IN:OUT` alone takes the straightness from the --model (`model`, absent: refused).
Expected<std::vector<CrossInput>> CrossInputs(const std::vector<std::string>& specs,
                                              const std::optional<std::string>& model) {
  std::vector<CrossInput> out;
  for (const std::string& s : specs) {
    const auto linear = [](char c) { return c == 'X' || c == 'Y' || c == 'Z'; };
    const bool from_model = s.size() == 3 && s[1] == ':';
    if (from_model && !model) {
      return UsageFailure("--cross " + s +
                          ": IN:OUT without =FILE takes the straightness from "
                          "--model, and there is none");
    }
    const bool shape = from_model || (s.size() > 4 && s[1] == ':' && s[3] == '=');
    const char in = shape ? static_cast<char>(std::toupper(static_cast<unsigned char>(s[0]))) : 0;
    const char o = shape ? static_cast<char>(std::toupper(static_cast<unsigned char>(s[2]))) : 0;
    if (!shape || !linear(in) || !linear(o) || in == o) {
      return UsageFailure("--cross " + s +
                          ": INPUT:OUTPUT=FILE (or INPUT:OUTPUT with --model) with two different "
                          "linear axes, e.g. X:Y=straightness_x_in_y.csv");
    }
    for (const CrossInput& c : out) {
      if (c.input.axis == in && c.output == o) {
        return UsageFailure("--cross " + s + ": " + std::string(1, in) + ":" + std::string(1, o) +
                            " is given twice");
      }
    }
    if (from_model) {
      out.push_back({{in, *model, true, o, nullptr}, o});
    } else {
      out.push_back({{in, s.substr(4), false, 0, nullptr}, o});
    }
  }
  return out;
}

Expected<exporters::StraightnessLine> ParseLine(const std::string& text) {
  if (text == "lsq") return exporters::StraightnessLine::kLeastSquares;
  if (text == "ends") return exporters::StraightnessLine::kEndPoints;
  if (text == "none") return exporters::StraightnessLine::kNone;
  return UsageFailure("--straightness-line " + text + ": lsq, ends or none");
}

Expected<Output> RunExportSiemens(Args& args, Context& ctx) {
  const Expected<std::vector<AxisInput>> pitch_inputs =
      PositioningInputs(args, /*model_axes=*/true);
  const std::optional<std::string> model = args.Value("--model");
  const std::vector<std::string> cross_specs = args.Values("--cross");
  const std::string line_text = args.Value("--straightness-line").value_or("lsq");
  const std::string out_file = args.Required("-o", "--output");
  const std::string mode = args.Value("--mode").value_or("auto");
  const long long encoder = args.Integer("--encoder").value_or(0);
  const long long max_points =
      args.Integer("--max-points")
          .value_or(static_cast<long long>(exporters::kSiemensDefaultMaxPoints));
  VOLCOMP_TRY_ASSIGN(const auto names, MachineAxisNames(args.Value("--names")));
  VOLCOMP_TRY_ASSIGN(const ControllerTableArgs table_args, ReadControllerTableArgs(args));
  args.Flag("--json");
  VOLCOMP_TRY(args.Finish());
  if (mode != "auto" && mode != "lec" && mode != "cec") {
    return UsageFailure("--mode " + mode + ": lec, cec or auto");
  }
  if (encoder != 0 && encoder != 1) {
    return UsageFailure("--encoder " + std::to_string(encoder) +
                        ": 0 (first measuring system) or 1 (second)");
  }
  if (max_points < 2) return UsageFailure("--max-points must be at least 2");
  if (!pitch_inputs.ok() && cross_specs.empty()) return Fail(pitch_inputs.error());
  std::vector<AxisInput> inputs = pitch_inputs.ok() ? *pitch_inputs : std::vector<AxisInput>();
  VOLCOMP_TRY_ASSIGN(std::vector<CrossInput> cross, CrossInputs(cross_specs, model));
  VOLCOMP_TRY_ASSIGN(const exporters::StraightnessLine line, ParseLine(line_text));
  if (!cross.empty() && mode == "lec") {
    return UsageFailure("--cross writes CEC tables: not with --mode lec");
  }
  // The model, read once for the pitch and the cross tables alike.
  std::vector<AxisInput> cross_inputs;
  for (const CrossInput& c : cross) cross_inputs.push_back(c.input);
  inputs.insert(inputs.end(), cross_inputs.begin(), cross_inputs.end());
  VOLCOMP_TRY(LoadModels(&inputs, ctx));
  for (std::size_t i = 0; i < cross.size(); ++i) {
    cross[i].input = inputs[inputs.size() - cross.size() + i];
  }
  inputs.resize(inputs.size() - cross.size());

  auto machine_name = [&](char axis) {
    const auto n = names.find(axis);
    return n != names.end() ? n->second : std::string(1, axis) + "1";
  };
  Output output;
  std::vector<exporters::SiemensAxis> axes;
  JsonValue axes_json = JsonValue::Array();
  bool bidirectional = false;
  for (const AxisInput& in : inputs) {
    VOLCOMP_TRY_ASSIGN(const AxisErrorTable t, LoadAxisErrorTable(in, table_args, ctx));
    const std::string warning = UncoveredWarning(t);
    if (!warning.empty()) output.warnings.push_back(warning);
    const std::string machine_axis = machine_name(in.axis);
    bidirectional = bidirectional || !t.table.reverse_um.empty();
    axes.push_back({machine_axis, in.path, t.table, "", ""});
    axes_json.Push(ErrorTableJson(t).Set("machine_axis", machine_axis));
  }
  JsonValue cross_json = JsonValue::Array();
  for (const CrossInput& c : cross) {
    VOLCOMP_TRY_ASSIGN(AxisErrorTable t, LoadAxisErrorTable(c.input, table_args, ctx));
    const auto ref = exporters::RemoveReferenceLine(&t.table, line);
    if (!ref.ok()) return Fail(Error::kInputInvalid, c.input.path + ": " + ref.error().message);
    const std::string what =
        std::string("straightness E_") + c.output + c.input.axis + ": the error of " + c.output +
        " over " + c.input.axis + ", about the " +
        (line == exporters::StraightnessLine::kLeastSquares ? "least-squares line"
         : line == exporters::StraightnessLine::kEndPoints  ? "end-point line"
                                                            : "readings as they are (no line)") +
        " (slope removed " + report::FormatNumber(ref->slope_um_per_m) +
        " um/m; squareness is separate)";
    axes.push_back(
        {machine_name(c.input.axis), c.input.path, t.table, machine_name(c.output), what});
    cross_json.Push(ErrorTableJson(t)
                        .Set("input_axis", machine_name(c.input.axis))
                        .Set("output_axis", machine_name(c.output))
                        .Set("line", line_text)
                        .Set("slope_removed_um_per_m", ref->slope_um_per_m));
  }
  exporters::SiemensOptions o;
  o.mode = mode == "cec" || (mode == "auto" && (bidirectional || !cross.empty()))
               ? exporters::SiemensMode::kCec
               : exporters::SiemensMode::kLec;
  o.encoder = static_cast<int>(encoder);
  o.max_points = static_cast<std::size_t>(max_points);
  o.unit = table_args.unit;
  const Expected<exporters::SiemensProgram> p = exporters::BuildSiemensProgram(axes, o);
  if (!p.ok()) return Fail(Error::kInputInvalid, p.error().message);
  VOLCOMP_TRY(tools::WriteTextFile(out_file, p->text));
  JsonValue tables = JsonValue::Array();
  for (const exporters::SiemensTableInfo& t : p->tables) {
    JsonValue j = JsonValue::Object();
    j.Set("machine_axis", t.machine_axis)
        .Set("output_axis", t.output_axis)
        .Set("cec_table", t.cec_table)
        .Set("direction", t.direction)
        .Set("points", uint64_t{t.points})
        .Set("min", t.min)
        .Set("max", t.max)
        .Set("step", t.step)
        .Set("rotary", t.rotary)
        .Set("unit", exporters::UnitName(o.unit, t.rotary))
        .Set("largest_value", t.largest_value);
    tables.Push(std::move(j));
  }
  JsonValue notes = JsonValue::Array();
  for (const std::string& n : p->notes) {
    output.warnings.push_back(n);
    notes.Push(n);
  }
  output.data = JsonValue::Object();
  output.data.Set("mode", std::string(o.mode == exporters::SiemensMode::kLec ? "LEC" : "CEC"))
      .Set("output", out_file)
      .Set("encoder", encoder)
      .Set("max_points", max_points)
      .Set("axes", std::move(axes_json))
      .Set("cross", std::move(cross_json))
      .Set("tables", std::move(tables))
      .Set("notes", std::move(notes));
  output.text = SiemensText;
  return output;
}

}  // namespace

const Command& ExportSiemensCommand() {
  static const Command kCommand{
      "export siemens",
      "SINUMERIK LEC ($AA_ENC_COMP) or CEC ($AN_CEC) compensation program from positioning tests",
      "",
      Join({PositioningFileOptions(),
            {ModelAxesOption(),
             {"--output", "-o", "FILE", nullptr, nullptr,
              "the program to write, e.g. AX_EEC.INI (required)"},
             {"--mode", nullptr, "lec|cec|auto", nullptr, "auto",
              "LEC: one table per axis (a two-direction test: their mean); CEC: a table per "
              "direction ($AN_CEC_DIRECTION 1 / -1); auto: CEC when a test has both directions"},
             {"--names", nullptr, "X=NAME,...", nullptr, nullptr,
              "machine axis name of an axis in the program (default: X1, Y1, Z1, A1, ...)"},
             {"--encoder", nullptr, "0|1", nullptr, "0", "LEC: the measuring system compensated"},
             {"--cross", nullptr, "IN:OUT=FILE", nullptr, nullptr,
              "a cross-axis CEC table from a straightness test: FILE's deviations are OUT's "
              "error (actual - nominal, um) at IN's targets, e.g. X:Y=str_xy.csv; IN:OUT alone "
              "takes E_OUT,IN from --model (repeatable)",
              true},
             {"--straightness-line", nullptr, "lsq|ends|none", nullptr, "lsq",
              "the reference line removed from a --cross test (ISO 230-1: least squares or end "
              "points; the axes' squareness is compensated separately)"},
             {"--max-points", nullptr, "N", nullptr, "200",
              "points per table the machine takes (MD38000 for LEC, MD18342 for CEC; 200 is the "
              "808D's LEC and the 828D's CEC limit)"}},
            ControllerTableOptions(
                "resample the test to this equal spacing (default: the test's positions, which "
                "must then be equally spaced)",
                "position where the table is 0: the reference point (K3 asks for 0 there; "
                "default: not zeroed)"),
            AllowFewRuns(),
            PositioningFormatOptions(),
            {{"--json", nullptr, nullptr, nullptr, nullptr, "machine-readable output"}}}),
      RunExportSiemens,
      "Each FILE is either the raw readings `evaluate positioning` reads (the mean per\n"
      "target and direction is used) or the mean deviations (position_mm, dev_forward_um\n"
      "[, dev_reverse_um]). Values: the measured error, actual - nominal, in mm (deg; inches\n"
      "on an inch machine), as the\n"
      "SINUMERIK K3 manual defines them (--negate flips them). See docs/pc-tool.md,\n"
      "\"Controller tables\"."};
  return kCommand;
}

}  // namespace volcomp::cli
