// `volcomp build axis`: AXIS1D tables (forward/reverse or forward + backlash) from positioning test
// results, one CSV per axis (raw readings or mean deviations; datasets/positioning_csv.hpp).
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "board_fit.hpp"
#include "build_options.hpp"
#include "choice_option.hpp"
#include "commands.hpp"
#include "option_groups.hpp"
#include "positioning_input.hpp"
#include "uncertainty_options.hpp"
#include "volcomp/builders/axis_section.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::cli {
namespace {

struct Input {
  char name;
  std::string path;
};

// --spacing X=S,...: the spacing of each input (0 = the test's own).
Expected<std::vector<double>> ParseSpacing(const std::optional<std::string>& text,
                                           const std::vector<Input>& inputs) {
  std::vector<double> spacing(inputs.size(), 0.0);
  if (!text) return spacing;
  VOLCOMP_TRY_ASSIGN(const auto assignments, image::ParseAxisAssignments(*text, "--spacing"));
  for (const auto& [name, value] : assignments) {
    bool found = false;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (inputs[i].name != name) continue;
      const auto v = tools::ParseDouble(value);
      if (!v || !(*v > 0)) {
        return UsageFailure("--spacing: axis " + std::string(1, name) + " needs a positive number");
      }
      spacing[i] = *v;
      found = true;
    }
    if (!found) return UsageFailure("--spacing: no input file for axis " + std::string(1, name));
  }
  return spacing;
}

JsonValue AxisData(const Input& in, const builders::Axis1dTable& t, bool rotary) {
  double max_forward = 0;
  for (double v : t.forward) max_forward = std::fmax(max_forward, std::fabs(v));
  JsonValue x = JsonValue::Object();
  x.Set("axis", std::string(1, in.name));
  x.Set("source", in.path);
  x.Set("nodes", uint64_t{t.forward.size()});
  x.Set("origin", t.origin);
  x.Set("spacing", t.spacing);
  x.Set("position_unit", rotary ? "deg" : "mm");
  x.Set("correction_unit", rotary ? "arcsec" : "µm");
  x.Set("max_forward_correction", max_forward);
  x.Set("reverse_table", !t.reverse.empty());
  x.Set("backlash", t.backlash);
  x.Set("max_residual", t.max_residual);
  return x;
}

// The test's U (k = 2) over its span, and how many measured deviations are smaller: their
// corrections are within the measurement's uncertainty (with a stated instrument or angle
// reference). Key U_um (linear) or U_arcsec (rotary).
const char* BelowUncertaintyKey(bool rotary) { return rotary ? "U_arcsec" : "U_um"; }

Expected<JsonValue> BelowUncertainty(const datasets::PositioningFile& file,
                                     const model::PositioningData& data,
                                     const metrology::PositioningUncertaintyInputs& given,
                                     std::vector<std::string>* warnings) {
  JsonValue j = JsonValue::Object();
  if (data.position.size() < 2) return j;
  VOLCOMP_TRY_ASSIGN(const auto in, metrology::CompleteFromPreamble(given, file.conditions));
  VOLCOMP_TRY_ASSIGN(
      const auto u,
      metrology::AxisUncertainty(
          in, data.rotary ? metrology::AxisKind::kRotary : metrology::AxisKind::kLinear,
          data.position.back() - data.position.front(), warnings));
  if (!u) return j;
  uint64_t points = 0, below = 0;
  for (const auto* devs : {&data.dev_forward, &data.dev_reverse}) {
    for (double d : *devs) {
      ++points;
      below += std::fabs(d) < u->span_u;
    }
  }
  j.Set(BelowUncertaintyKey(data.rotary), u->span_u).Set("points", points);
  j.Set("points_below_U", below);
  return j;
}

void BuildAxisText(const JsonValue& d, std::ostream& out) {
  out << "volcomp build axis\n";
  for (const JsonValue& a : d.get("axes")->array) {
    const char* unit = a.get("correction_unit")->string.c_str();
    char line[256];
    std::snprintf(line, sizeof(line),
                  "  axis %s: %lld nodes from %.6g every %.6g %s, largest forward correction %.3f "
                  "%s, %s, backlash %.3f %s\n",
                  a.get("axis")->string.c_str(), static_cast<long long>(a.get("nodes")->integer),
                  a.get("origin")->number, a.get("spacing")->number,
                  a.get("position_unit")->string.c_str(), a.get("max_forward_correction")->number,
                  unit, a.get("reverse_table")->boolean ? "reverse table" : "no reverse table",
                  a.get("backlash")->number, unit);
    out << line;
    const JsonValue& u = *a.get("uncertainty");
    if (const JsonValue* below = u.get("points_below_U")) {
      std::snprintf(
          line, sizeof(line),
          "    U (k = 2) of the test %.2f %s: %lld of %lld measured deviations are smaller "
          "(their corrections are within the measurement's uncertainty)\n",
          u.get(BelowUncertaintyKey(a.get("position_unit")->string == "deg"))->number, unit,
          static_cast<long long>(below->integer), static_cast<long long>(u.get("points")->integer));
      out << line;
    }
  }
  out << "  wrote " << d.get("image")->string << " (" << d.get("bytes")->integer << " bytes)\n";
}

Expected<Output> RunBuildAxis(Args& args, Context& ctx) {
  std::vector<Input> inputs;
  for (const char* n : {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"}) {
    const std::string opt = std::string("--") + static_cast<char>(n[0] - 'A' + 'a');
    if (auto p = args.Value(opt)) inputs.push_back({n[0], *p});
  }
  if (inputs.empty()) return UsageFailure("give at least one axis file, e.g. --x x.csv");
  if (inputs.size() > table::kMaxAxes) return UsageFailure("at most 6 axes");
  const std::string out_path = args.Required("-o", "--output");
  VOLCOMP_TRY(args.status());
  builders::Axis1dOptions opt;
  const std::string reverse = args.Value("--reverse").value_or("tables");
  VOLCOMP_TRY_ASSIGN(opt.reverse, ParseChoice<builders::ReverseMode>(
                                      "--reverse", reverse,
                                      {{"tables", builders::ReverseMode::kTables},
                                       {"backlash", builders::ReverseMode::kBacklash},
                                       {"mean", builders::ReverseMode::kMean}}));
  VOLCOMP_TRY_ASSIGN(const std::vector<double> spacing,
                     ParseSpacing(args.Value("--spacing"), inputs));
  const bool wrap = args.Flag("--wrap");
  std::vector<char> names;
  for (const Input& in : inputs) names.push_back(in.name);
  image::ImageRequest req;
  VOLCOMP_TRY_ASSIGN(req.axes, ParseAxisResolutions(args, names));
  VOLCOMP_TRY(ParseImageOptions(args, &req));
  VOLCOMP_TRY_ASSIGN(const std::optional<BoardFileCheck> board, ParseBoardFileCheck(args));
  VOLCOMP_TRY_ASSIGN(const datasets::PositioningReadOptions read,
                     ParsePositioningReadOptions(args));
  VOLCOMP_TRY_ASSIGN(const metrology::PositioningUncertaintyInputs uncertainty,
                     ReadPositioningUncertainty(args, ctx));
  VOLCOMP_TRY(args.Finish());

  Output output;
  JsonValue axes = JsonValue::Array();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    VOLCOMP_TRY_ASSIGN(const datasets::PositioningFile file,
                       ReadPositioningArgument(inputs[i].path, read, ctx));
    VOLCOMP_TRY_ASSIGN(const model::PositioningData data, datasets::PositioningMeans(file));
    for (const std::string& w : data.warnings) ctx.err << "warning: " << w << "\n";
    builders::Axis1dOptions o = opt;
    o.spacing = spacing[i];
    const Expected<builders::AxisSection> axis =
        builders::BuildAxisSection(data, o, req.axes[i], static_cast<uint8_t>(i), wrap);
    if (!axis.ok()) return Fail(Error::kInputInvalid, inputs[i].path + ": " + axis.error().message);
    req.axis_tables.push_back(axis->section);
    req.info.emplace(std::string("source_") + inputs[i].name, inputs[i].path);
    JsonValue axis_data =
        AxisData(inputs[i], axis->table, req.axes[i].kind == table::AxisKind::kRotary);
    std::vector<std::string> u_warnings;
    VOLCOMP_TRY_ASSIGN(JsonValue below, BelowUncertainty(file, data, uncertainty, &u_warnings));
    for (const std::string& w : u_warnings) {
      output.warnings.push_back(std::string(1, inputs[i].name) + ": " + w);
    }
    axis_data.Set("uncertainty", std::move(below));
    axes.Push(std::move(axis_data));
  }
  req.info.emplace("builder", "volcomp build axis");
  req.info.emplace("reverse", reverse);
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> bytes, image::BuildImage(req));
  JsonValue board_check;
  if (board) VOLCOMP_TRY(CheckImageAgainstBoardFile(*board, bytes, &output.warnings, &board_check));
  VOLCOMP_TRY(tools::WriteFileBytes(out_path, bytes));
  output.data = JsonValue::Object();
  output.data.Set("image", out_path)
      .Set("bytes", uint64_t{bytes.size()})
      .Set("reverse", reverse)
      .Set("axes", std::move(axes));
  if (board) output.data.Set("board_check", std::move(board_check));
  output.text = BuildAxisText;
  return output;
}

}  // namespace

const Command& BuildAxisCommand() {
  static const Command kCommand{
      "build axis",
      "AXIS1D image from positioning tests (raw readings or mean deviations)",
      "",
      Join({PositioningFileOptions(),
            PositioningFormatOptions(),
            {{"--output", "-o", "IMAGE", nullptr, nullptr, "image file to write (required)"}},
            ResolutionOptions(),
            {{"--reverse", nullptr, "tables|backlash|mean", nullptr, "tables",
              "negative-direction handling"},
             {"--spacing", nullptr, "X=S,...", "mm (deg for A, B, C)", nullptr,
              "table spacing per axis (default: the test's, or its smallest gap)"},
             {"--wrap", nullptr, nullptr, nullptr, nullptr,
              "rotary table spanning exactly 360° wraps around"}},
            ImageOptions(),
            BoardFileOptions(),
            LengthUncertaintyOptions(),
            AngleUncertaintyOptions()}),
      RunBuildAxis,
      PositioningFileNotes()};
  return kCommand;
}

}  // namespace volcomp::cli
