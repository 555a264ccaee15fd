// The export commands' shared inputs (see export_axes.hpp).
#include "export_axes.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "choice_option.hpp"
#include "positioning_input.hpp"
#include "volcomp/datasets/model_file.hpp"
#include "volcomp/datasets/positioning_csv.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::cli {
namespace {

constexpr const char* kAxes = "XYZABCUVW";

}  // namespace

args::OptionSpec ModelAxesOption() {
  return {"--model",
          nullptr,
          "s500|FILE",
          nullptr,
          nullptr,
          "a 21-parameter model (conf, Etalon, ISG-CSV): its positioning errors E_XX, E_YY, "
          "E_ZZ are the tables of the axes X, Y, Z no file gives (one direction)"};
}

Expected<std::vector<AxisInput>> PositioningInputs(Args& args, bool model_axes) {
  std::vector<AxisInput> inputs;
  const std::optional<std::string> model = model_axes ? args.Value("--model") : std::nullopt;
  for (int i = 0; kAxes[i] != '\0'; ++i) {
    const std::string opt = std::string("--") + static_cast<char>(kAxes[i] - 'A' + 'a');
    if (auto p = args.Value(opt)) {
      inputs.push_back({kAxes[i], *p, false, 0, nullptr});
    } else if (model && i < 3) {
      inputs.push_back({kAxes[i], *model, true, 0, nullptr});
    }
  }
  if (inputs.empty()) {
    return UsageFailure(model_axes ? "give at least one axis file, e.g. --x x.csv, or --model FILE"
                                   : "give at least one axis file, e.g. --x x.csv");
  }
  return inputs;
}

Expected<model::Model> LoadModelArgument(const std::string& name, Context& ctx) {
  if (name == "s500") return datasets::S500Model();
  VOLCOMP_TRY_ASSIGN(datasets::LoadedModel loaded, datasets::LoadModelFile(name));
  for (const std::string& w : loaded.warnings) ctx.err << "warning: " << w << "\n";
  return std::move(loaded.model);
}

Expected<std::map<char, double>> ParseAxisNumbers(const std::optional<std::string>& text,
                                                  const std::string& option,
                                                  bool positive) {
  std::map<char, double> numbers;
  if (!text) return numbers;
  VOLCOMP_TRY_ASSIGN(const auto assignments, image::ParseAxisAssignments(*text, option));
  for (const auto& [name, value] : assignments) {
    const auto v = tools::ParseDouble(value);
    if (!v || !std::isfinite(*v) || (positive && !(*v > 0))) {
      return UsageFailure(option + ": " + std::string(1, name) +
                          (positive ? " must be > 0" : " must be a number"));
    }
    numbers[name] = *v;
  }
  return numbers;
}

Expected<std::map<char, int>> ParseAxisNumberMap(const std::optional<std::string>& text,
                                                 const std::string& option,
                                                 const std::string& what,
                                                 int first,
                                                 int min,
                                                 int max) {
  std::map<char, int> number;
  for (int i = 0; kAxes[i] != '\0'; ++i) number[kAxes[i]] = first + i;
  if (!text) return number;
  VOLCOMP_TRY_ASSIGN(const auto assignments, image::ParseAxisAssignments(*text, option));
  for (const auto& [name, value] : assignments) {
    const auto v = tools::ParseInteger(value);
    if (!v || *v < min || *v > max) {
      return UsageFailure(option + ": " + what + " of " + std::string(1, name) + " must be " +
                          std::to_string(min) + ".." + std::to_string(max));
    }
    number[name] = static_cast<int>(*v);
  }
  return number;
}

namespace {

// The model's error of axis `in.axis` in direction `in.direction` (its own: positioning) as a
// one-direction test at the model's positions.
Expected<model::PositioningData> ModelAxisTest(const AxisInput& in, Context& ctx) {
  const int axis = in.axis - 'X';
  const int direction = (in.direction != 0 ? in.direction : in.axis) - 'X';
  if (axis < 0 || axis > 2 || direction < 0 || direction > 2) {
    return UsageFailure(std::string("--model: a model has the linear axes X, Y, Z only, not ") +
                        in.axis);
  }
  std::shared_ptr<const model::Model> m = in.model;
  if (!m) {
    VOLCOMP_TRY_ASSIGN(model::Model read, LoadModelArgument(in.path, ctx));
    m = std::make_shared<const model::Model>(std::move(read));
  }
  const model::AxisErrorTable& t = m->axes[static_cast<std::size_t>(axis)];
  model::PositioningData d;
  for (std::size_t i = 0; i < t.size(); ++i) {
    d.position.push_back(t.position_mm(i));
    d.dev_forward.push_back(t.row(i).linear_um[direction]);
  }
  if (d.position.size() < 2) {
    return Fail(Error::kInputInvalid, in.path + ": the model's " + in.axis +
                                          " table has fewer "
                                          "than 2 positions");
  }
  return d;
}

}  // namespace

Expected<void> LoadModels(std::vector<AxisInput>* inputs, Context& ctx) {
  std::map<std::string, std::shared_ptr<const model::Model>> read;
  for (AxisInput& in : *inputs) {
    if (!in.from_model) continue;
    auto& m = read[in.path];
    if (!m) {
      VOLCOMP_TRY_ASSIGN(model::Model loaded, LoadModelArgument(in.path, ctx));
      m = std::make_shared<const model::Model>(std::move(loaded));
    }
    in.model = m;
  }
  return {};
}

Expected<model::PositioningData> LoadAxisTest(const AxisInput& in,
                                              const datasets::PositioningReadOptions& read,
                                              const metrology::GroupingOptions& grouping,
                                              Context& ctx,
                                              datasets::PositioningFormat* format) {
  if (in.from_model) return ModelAxisTest(in, ctx);
  const std::string& path = in.path;
  VOLCOMP_TRY_ASSIGN(const datasets::PositioningFile input,
                     ReadPositioningArgument(path, read, ctx));
  if (format != nullptr) *format = input.format;
  VOLCOMP_TRY_ASSIGN(model::PositioningData data, datasets::PositioningMeans(input, grouping));
  for (const std::string& w : data.warnings) ctx.err << "warning: " << w << "\n";
  return data;
}

args::OptionSpec MachineUnitsOption(const char* metric_only) {
  if (metric_only != nullptr) {
    return {"--units", nullptr,
            "mm",      nullptr,
            "mm",      "mm only: this controller's tables are in mm whatever the machine's unit"};
  }
  return {"--units",
          nullptr,
          "mm|in",
          nullptr,
          "mm",
          "the machine's length unit: of the table written and of the positions given "
          "(--spacing, --reference); a rotary axis is in deg with either"};
}

Expected<exporters::LengthUnit> ParseMachineUnits(Args& args, const char* metric_only) {
  const std::string word = args.Value("--units").value_or("mm");
  if (metric_only != nullptr) {
    return ParseChoice<exporters::LengthUnit>("--units", word, {{"mm", exporters::LengthUnit::kMm}},
                                              metric_only);
  }
  return ParseChoice<exporters::LengthUnit>(
      "--units", word, {{"mm", exporters::LengthUnit::kMm}, {"in", exporters::LengthUnit::kInch}});
}

Options ControllerTableOptions(const char* spacing_help,
                               const char* reference_help,
                               const char* metric_only) {
  const char* unit = metric_only != nullptr ? "mm (deg for A, B, C)" : "mm or in (deg for A, B, C)";
  return {MachineUnitsOption(metric_only),
          {"--spacing", nullptr, "X=S,...", unit, nullptr, spacing_help},
          {"--reference", nullptr, "X=P,...", unit, nullptr, reference_help},
          {"--negate", nullptr, nullptr, nullptr, nullptr,
           "flip the sign of every value, for a control that proves to take the other sign"}};
}

Expected<ControllerTableArgs> ReadControllerTableArgs(Args& args, const char* metric_only) {
  ControllerTableArgs a;
  VOLCOMP_TRY_ASSIGN(a.unit, ParseMachineUnits(args, metric_only));
  VOLCOMP_TRY_ASSIGN(a.spacing, ParseAxisNumbers(args.Value("--spacing"), "--spacing", true));
  VOLCOMP_TRY_ASSIGN(a.reference,
                     ParseAxisNumbers(args.Value("--reference"), "--reference", false));
  a.negate = args.Flag("--negate");
  VOLCOMP_TRY_ASSIGN(a.read, ParsePositioningReadOptions(args));
  a.grouping.allow_few_approaches = args.Flag("--allow-few-runs");
  return a;
}

Expected<AxisErrorTable> LoadAxisErrorTable(const AxisInput& input,
                                            const ControllerTableArgs& options,
                                            Context& ctx,
                                            bool reference_at_first) {
  VOLCOMP_TRY_ASSIGN(const model::PositioningData data,
                     LoadAxisTest(input, options.read, options.grouping, ctx));
  exporters::ErrorTableOptions o;
  o.unit = options.unit;
  o.negate = options.negate;
  if (const auto s = options.spacing.find(input.axis); s != options.spacing.end()) {
    o.spacing = s->second;
  }
  if (const auto r = options.reference.find(input.axis); r != options.reference.end()) {
    o.zero_at = r->second;
  } else if (reference_at_first) {
    o.zero_at = data.position.front();
  }
  const Expected<exporters::ErrorTable> t = exporters::BuildErrorTable(data, o);
  if (!t.ok()) return Fail(Error::kInputInvalid, input.path + ": " + t.error().message);
  return AxisErrorTable{input, *t};
}

JsonValue ErrorTableJson(const AxisErrorTable& axis) {
  const exporters::ErrorTable& t = axis.table;
  double largest = 0;
  for (const double e : t.forward_um) largest = std::fmax(largest, std::fabs(e));
  for (const double e : t.reverse_um) largest = std::fmax(largest, std::fabs(e));
  JsonValue j = JsonValue::Object();
  j.Set("axis", std::string(1, axis.input.axis))
      .Set("source", axis.input.path)
      .Set("rotary", t.rotary)
      .Set("unit", exporters::UnitName(t.unit, t.rotary))
      .Set("points", uint64_t{t.position.size()})
      .Set("from", t.position.front())
      .Set("to", t.position.back())
      .Set("spacing", t.spacing)
      .Set("tested_to", t.tested_to)
      .Set("uncovered", t.uncovered)
      .Set("bidirectional", !t.reverse_um.empty())
      .Set("negated", t.negated)
      .Set("largest_error", largest);
  if (t.unit == exporters::LengthUnit::kInch && !t.rotary) {
    // 1 µin = 0.0254 µm; to 1e-6 µin, so that 5.08 µm reads 200 µin.
    j.Set("largest_error_uin",
          std::round(largest / metrology::kMicrometresPerMicroinch * 1e6) / 1e6);
  }
  if (t.zero_at) j.Set("reference", *t.zero_at);
  return j;
}

std::string ErrorTableText(const JsonValue& a) {
  const bool rotary = a.get("rotary")->boolean;
  const char* unit = a.get("unit")->string.c_str();
  char s[400];
  std::snprintf(s, sizeof s, "  axis %s: %lld points from %g to %g %s",
                a.get("axis")->string.c_str(), static_cast<long long>(a.get("points")->integer),
                a.get("from")->number, a.get("to")->number, unit);
  std::string line = s;
  if (a.get("spacing")->number > 0) {
    std::snprintf(s, sizeof s, " every %g %s", a.get("spacing")->number, unit);
    line += s;
  }
  line += a.get("bidirectional")->boolean ? ", both directions" : ", one direction";
  std::snprintf(s, sizeof s, ", largest error %.2f %s", a.get("largest_error")->number,
                rotary ? "arcsec" : "um");
  line += s;
  if (const JsonValue* uin = a.get("largest_error_uin")) {
    std::snprintf(s, sizeof s, " (%.0f uin)", uin->number);
    line += s;
  }
  if (const JsonValue* r = a.get("reference")) {
    std::snprintf(s, sizeof s, ", zero at %g %s", r->number, unit);
    line += s;
  } else {
    line += ", not zeroed";
  }
  if (a.get("negated")->boolean) line += ", NEGATED";
  return line + " (" + a.get("source")->string + ")\n";
}

std::string UncoveredWarning(const AxisErrorTable& axis) {
  const exporters::ErrorTable& t = axis.table;
  if (!(t.uncovered > 0)) return "";
  char s[300];
  std::snprintf(s, sizeof s,
                "%s: the table ends at %g, the test at %g %s: the last %g %s tested are not in "
                "it (a --spacing that divides the travel covers it all)",
                axis.input.path.c_str(), t.position.back(), t.tested_to,
                exporters::UnitName(t.unit, t.rotary), t.uncovered,
                exporters::UnitName(t.unit, t.rotary));
  return s;
}

}  // namespace volcomp::cli
