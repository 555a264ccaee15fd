// Option groups of the table builders (see build_options.hpp).
#include "build_options.hpp"

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "choice_option.hpp"
#include "volcomp/datasets/model_file.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/image/axis_units.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::cli {
namespace {

// The index of X, Y or Z; -1 for another axis.
int XyzIndex(char name) { return name == 'X' ? 0 : name == 'Y' ? 1 : name == 'Z' ? 2 : -1; }

}  // namespace

Expected<std::optional<datasets::ModelFileFormat>> ParseModelFormat(Args& args,
                                                                    const std::string& option) {
  const auto word = args.Value(option);
  VOLCOMP_TRY(args.status());
  if (!word) return std::optional<datasets::ModelFileFormat>();
  using datasets::ModelFileFormat;
  VOLCOMP_TRY_ASSIGN(const ModelFileFormat f,
                     ParseChoice<ModelFileFormat>(option, *word,
                                                  {{"conf", ModelFileFormat::kConfig},
                                                   {"etalon", ModelFileFormat::kEtalon},
                                                   {"isg", ModelFileFormat::kIsgCsv}}));
  return std::optional<ModelFileFormat>(f);
}

Expected<model::Model> ParseModelOptions(Args& args,
                                         std::optional<datasets::ModelFileFormat> format,
                                         ModelSource* source) {
  const std::string spec = args.Required("--model");
  VOLCOMP_TRY(args.status());
  model::Model m;
  source->spec = spec;
  if (spec == "s500") {
    if (format)
      return UsageFailure("a model file format was given, but --model s500 is the built-in model");
    m = datasets::S500Model();
    source->format = "builtin";
  } else {
    VOLCOMP_TRY_ASSIGN(datasets::LoadedModel loaded, datasets::LoadModelFile(spec, format));
    m = std::move(loaded.model);
    source->format = datasets::ModelFileFormatName(loaded.format);
    source->detected = loaded.format_detected;
    source->warnings = std::move(loaded.warnings);
  }
  if (args.Flag("--no-squareness")) m.squareness = model::Squareness{};
  if (auto f = args.Value("--formulation")) {
    VOLCOMP_TRY_ASSIGN(m.formulation, ParseChoice<model::Formulation>(
                                          "--formulation", *f,
                                          {{"physical", model::Formulation::kPhysical},
                                           {"dissertation", model::Formulation::kDissertation}}));
  }
  if (auto o = args.Value("--order")) {
    VOLCOMP_TRY_ASSIGN(m.order,
                       ParseChoice<model::Order>("--order", *o,
                                                 {{"first", model::Order::kFirst},
                                                  {"exact", model::Order::kSecond},
                                                  {"second", model::Order::kSecond, false}},
                                                 "second"));
  }
  if (auto c = args.Value("--dissertation-case")) {
    VOLCOMP_TRY_ASSIGN(m.dissertation_case, ParseChoice<model::DissertationCase>(
                                                "--dissertation-case", *c,
                                                {{"plus", model::DissertationCase::kPlus},
                                                 {"minus", model::DissertationCase::kMinus}}));
  }
  if (auto k = args.Number("--angle-scale")) m.angle_scale = *k;
  VOLCOMP_TRY(args.status());
  if (auto t = args.Value("--tool-offset-mm")) {
    std::stringstream ss(*t);
    std::string part;
    std::vector<double> v;
    while (std::getline(ss, part, ',')) {
      const auto d = tools::ParseDouble(part);
      if (!d) return UsageFailure("--tool-offset-mm: \"" + part + "\" is not a number");
      v.push_back(*d);
    }
    if (v.size() != 3) return UsageFailure("--tool-offset-mm needs X,Y,Z");
    m.tool_offset_mm = {v[0], v[1], v[2]};
  }
  if (const Outcome valid = model::ValidateModel(m); !valid.ok()) {
    return UsageFailure(valid.error().message);
  }
  return m;
}

JsonValue ModelSourceJson(const ModelSource& source) {
  JsonValue warnings = JsonValue::Array();
  for (const std::string& w : source.warnings) warnings.Push(w);
  JsonValue j = JsonValue::Object();
  j.Set("spec", source.spec)
      .Set("format", source.format)
      .Set("detected", source.detected)
      .Set("warnings", std::move(warnings));
  return j;
}

Expected<std::array<double, 3>> ParseXyzNumbers(const std::string& text,
                                                const std::string& option,
                                                bool all_required) {
  std::array<double, 3> out = {NAN, NAN, NAN};
  if (const auto single = tools::ParseDouble(text)) {
    out = {*single, *single, *single};
    return out;
  }
  VOLCOMP_TRY_ASSIGN(const auto assignments, image::ParseAxisAssignments(text, option));
  for (const auto& [name, value] : assignments) {
    const int a = XyzIndex(name);
    if (a < 0) return UsageFailure(option + ": only X, Y and Z apply here");
    const auto v = tools::ParseDouble(value);
    if (!v) return UsageFailure(option + ": \"" + value + "\" is not a number");
    out[static_cast<std::size_t>(a)] = *v;
  }
  if (all_required) {
    for (double v : out) {
      if (std::isnan(v)) return UsageFailure(option + ": give X, Y and Z (or one number for all)");
    }
  }
  return out;
}

Expected<std::vector<image::AxisDef>> ParseAxisResolutions(Args& args,
                                                           const std::vector<char>& names) {
  return image::MakeAxisDefs(names, args.Value("--resolution-nm").value_or(""),
                             args.Value("--steps-per-unit").value_or(""));
}

Outcome ParseImageOptions(Args& args, image::ImageRequest* request) {
  using table::ElementType;
  VOLCOMP_TRY_ASSIGN(request->element,
                     ParseChoice<ElementType>(
                         "--element", args.Value("--element").value_or("int16"),
                         {{table::ElementTypeName(ElementType::kInt16), ElementType::kInt16},
                          {table::ElementTypeName(ElementType::kInt32), ElementType::kInt32},
                          {table::ElementTypeName(ElementType::kFloat32), ElementType::kFloat32}}));
  const auto frac_bits = args.Integer("--frac-bits");
  VOLCOMP_TRY(args.status());
  if (frac_bits) {
    if (*frac_bits < 0 || *frac_bits > 8) return UsageFailure("--frac-bits must be 0..8");
    request->frac_bits = static_cast<uint8_t>(*frac_bits);
  }
  const auto id = args.Integer("--table-id");
  VOLCOMP_TRY(args.status());
  if (id) {
    if (*id < 1 || *id > 0xFFFFFFFFll) {
      return UsageFailure("--table-id must be 1..4294967295 (0 means no table active)");
    }
    request->table_id = static_cast<uint32_t>(*id);
  }
  for (const std::string& kv : args.Values("--info")) {
    const std::size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) return UsageFailure("--info takes KEY=VALUE");
    request->info[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return Outcome::Ok();
}

Expected<GridCommand> ParseGridCommand(Args& args, const builders::GridSource& source) {
  GridCommand c;
  c.output = args.Required("-o", "--output");
  VOLCOMP_TRY(args.status());
  VOLCOMP_TRY_ASSIGN(c.request.axes, ParseAxisResolutions(args, {'X', 'Y', 'Z'}));
  c.grid.min_mm = source.min_mm;
  c.grid.max_mm = source.max_mm;
  c.grid.natural_spacing_mm = source.natural_spacing_mm;
  for (std::size_t a = 0; a < 3; ++a) c.grid.step_mm[a] = c.request.axes[a].units_per_step();
  if (auto r = args.Value("--range")) {
    VOLCOMP_TRY_ASSIGN(const auto ranges, image::ParseAxisAssignments(*r, "--range"));
    for (const auto& [name, value] : ranges) {
      const int a = XyzIndex(name);
      const std::size_t colon = value.find(':');
      double lo = NAN, hi = NAN;
      if (colon != std::string::npos) {
        lo = tools::ParseDouble(value.substr(0, colon)).value_or(NAN);
        hi = tools::ParseDouble(value.substr(colon + 1)).value_or(NAN);
      }
      if (a < 0 || !(hi > lo)) {
        return UsageFailure("--range: expected AXIS=MIN:MAX with MIN < MAX (mm), got \"" +
                            std::string(1, name) + "=" + value + "\"");
      }
      c.grid.min_mm[static_cast<std::size_t>(a)] = lo;
      c.grid.max_mm[static_cast<std::size_t>(a)] = hi;
    }
  }
  const auto spacing = args.Value("--spacing-mm");
  const auto max_err = args.Number("--max-interp-error-um");
  VOLCOMP_TRY(args.status());
  if (spacing && max_err) {
    return UsageFailure("give either --spacing-mm or --max-interp-error-um, not both");
  }
  if (spacing) {
    VOLCOMP_TRY_ASSIGN(c.grid.spacing_mm, ParseXyzNumbers(*spacing, "--spacing-mm", true));
    for (double h : c.grid.spacing_mm) {
      if (!(h > 0)) return UsageFailure("--spacing-mm must be positive");
    }
  }
  if (max_err) {
    if (!(*max_err > 0)) return UsageFailure("--max-interp-error-um must be positive");
    c.grid.max_interp_error_um = *max_err;
  }
  const auto bound = args.Number("--max-correction-um");
  VOLCOMP_TRY(args.status());
  if (bound) {
    if (!(*bound > 0)) return UsageFailure("--max-correction-um must be positive");
    c.grid.max_correction_um = *bound;
  }
  VOLCOMP_TRY(ParseImageOptions(args, &c.request));
  VOLCOMP_TRY_ASSIGN(c.board, ParseBoardFileCheck(args));
  args.Flag("--json");  // the command layer prints the report as JSON
  return c;
}

}  // namespace volcomp::cli
