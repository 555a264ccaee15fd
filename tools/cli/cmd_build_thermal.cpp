// `volcomp build thermal FILE|-`: the board's thermal model fitted to a drift test by least squares
// (builders/thermal_fit.hpp), reported as text or JSON; with --image IN -o OUT, a new image: IN's
// geometric sections and the fitted THERMAL section (image/image_thermal.hpp).
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "file_arguments.hpp"
#include "option_groups.hpp"
#include "volcomp/builders/thermal_fit.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/image/image_thermal.hpp"
#include "volcomp/metrology/drift_test.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using report::FormatFixed;
using report::FormatNumber;
using report::FormatSigned;

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    std::string item = text.substr(start, end - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    out.push_back(item);
    start = end + 1;
  }
  return out;
}

// --reference-C T (every chosen channel) or NAME=T,NAME=T.
Outcome ParseReferences(const std::optional<std::string>& text, builders::ThermalFitOptions* o) {
  if (!text) return Outcome::Ok();
  if (const auto all = tools::ParseDouble(*text)) {
    o->reference_C = *all;
    return Outcome::Ok();
  }
  for (const std::string& item : SplitList(*text)) {
    const std::size_t eq = item.find('=');
    const auto value =
        eq == std::string::npos ? std::nullopt : tools::ParseDouble(item.substr(eq + 1));
    if (eq == 0 || !value) {
      return UsageFailure("--reference-C takes a temperature in °C or NAME=T,...: \"" + item +
                          "\"");
    }
    if (!o->reference_by.emplace(item.substr(0, eq), *value).second) {
      return UsageFailure("--reference-C: channel " + item.substr(0, eq) + " is given twice");
    }
  }
  return Outcome::Ok();
}

JsonValue FitJson(const builders::ThermalFit& fit, const thermal::ThermalModel* model) {
  JsonValue channels = JsonValue::Array();
  for (const builders::ThermalFitChannel& c : fit.channels) {
    JsonValue o = JsonValue::Object();
    o.Set("channel", uint64_t{c.number});
    o.Set("name", c.name);
    o.Set("reference_C", c.reference_C);
    o.Set("reference_from", c.reference_given ? "--reference-C" : "first reading");
    o.Set("min_C", c.min_C);
    o.Set("max_C", c.max_C);
    if (model != nullptr) {
      o.Set("reference_cC", int64_t{model->reference_cC[c.number]});
      o.Set("calibrated_low_cC", int64_t{model->calibrated_low_cC[c.number]});
      o.Set("calibrated_high_cC", int64_t{model->calibrated_high_cC[c.number]});
    }
    channels.Push(std::move(o));
  }
  JsonValue axes = JsonValue::Array();
  for (const builders::ThermalAxisFit& a : fit.axes) {
    JsonValue o = JsonValue::Object();
    o.Set("axis", std::string(1, a.name));
    o.Set("p0_mm", a.p0_mm);
    o.Set("reach_mm", a.reach_mm);
    o.Set("reach_from", a.reach_from_image ? "image" : "points");
    o.Set("samples", uint64_t{a.samples});
    o.Set("offset_um_per_K", JsonValue::Numbers(a.offset_um_per_K));
    o.Set("slope_um_per_K_m", JsonValue::Numbers(a.slope_um_per_K_m));
    o.Set("drift_rms_um", a.drift_rms_um);
    o.Set("residual_rms_um", a.residual_rms_um);
    o.Set("residual_max_um", a.residual_max_um);
    o.Set("explained", a.explained);
    o.Set("condition", a.condition);
    axes.Push(std::move(o));
  }
  JsonValue j = JsonValue::Object();
  j.Set("channels", std::move(channels));
  j.Set("max_condition", fit.max_condition);
  j.Set("axes", std::move(axes));
  return j;
}

void BuildThermalText(const JsonValue& d, std::ostream& out) {
  out << "thermal model from " << d.get("source")->string
      << " (a correction: a drift of +d is fitted as -d)\n";
  const auto& channels = d.get("channels")->array;
  out << "channels:\n";
  for (const JsonValue& c : channels) {
    out << "  " << c.get("channel")->integer << " " << c.get("name")->string << ": reference "
        << FormatFixed(c.get("reference_C")->number, 2) << " °C ("
        << c.get("reference_from")->string << "), calibrated over "
        << FormatFixed(c.get("min_C")->number, 2) << " .. "
        << FormatFixed(c.get("max_C")->number, 2) << " °C\n";
  }
  for (const JsonValue& a : d.get("axes")->array) {
    out << "axis " << a.get("axis")->string << ": p0 " << FormatNumber(a.get("p0_mm")->number, 6)
        << " mm, reach " << FormatNumber(a.get("reach_mm")->number, 6) << " mm (from the "
        << a.get("reach_from")->string << "), " << a.get("samples")->integer
        << " samples, condition " << FormatNumber(a.get("condition")->number, 3) << " (limit "
        << FormatNumber(d.get("max_condition")->number, 3) << ")\n";
    out << "  channel         offset µm/K   slope µm/(K·m)\n";
    for (std::size_t j = 0; j < channels.size(); ++j) {
      char line[160];
      std::snprintf(line, sizeof line, "  %-14s %12s %16s\n",
                    channels[j].get("name")->string.c_str(),
                    FormatSigned(a.get("offset_um_per_K")->array[j].number, 4).c_str(),
                    FormatSigned(a.get("slope_um_per_K_m")->array[j].number, 4).c_str());
      out << line;
    }
    const JsonValue& explained = *a.get("explained");
    out << "  drift RMS " << FormatFixed(a.get("drift_rms_um")->number, 3) << " µm; residual RMS "
        << FormatFixed(a.get("residual_rms_um")->number, 3) << " µm, max "
        << FormatFixed(a.get("residual_max_um")->number, 3) << " µm; explained "
        << (explained.is_number() ? FormatFixed(100.0 * explained.number, 2) + " %" : "n/a")
        << " of the drift variance\n";
  }
  const JsonValue* image = d.get("image");
  if (image != nullptr && !image->is_null()) {
    out << "wrote " << image->get("output")->string << ": " << image->get("bytes")->integer
        << " bytes, table id " << image->get("table_id")->integer << ", CRC-32 "
        << image->get("crc32")->string << "; " << image->get("input")->string
        << "'s geometric sections and the THERMAL section"
        << (image->get("replaced_thermal")->boolean ? " (replacing its earlier one)" : "") << "\n";
  } else {
    out << "no image written (give --image IN -o OUT)\n";
  }
}

Expected<Output> RunBuildThermal(Args& args, Context& ctx) {
  args.Flag("--json");  // the command layer prints the data as JSON
  builders::ThermalFitOptions o;
  if (const auto channels = args.Value("--channels")) o.channels = SplitList(*channels);
  const auto references = args.Value("--reference-C");
  if (const auto limit = args.Number("--max-condition")) o.max_condition = *limit;
  const auto image_path = args.Value("--image");
  const auto out_path = args.Value("--output", "-o");
  const auto id = args.Integer("--table-id");
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("give exactly one drift test file (or - for stdin)");
  VOLCOMP_TRY(ParseReferences(references, &o));
  if (!(o.max_condition >= 1)) return UsageFailure("--max-condition must be 1 or more");
  if (image_path.has_value() != out_path.has_value()) {
    return UsageFailure("--image IN and -o OUT go together: the new image is IN with the model");
  }
  if (id && !image_path) return UsageFailure("--table-id needs --image IN -o OUT");
  image::ThermalImageOptions image_options;
  if (id) {
    if (*id < 1 || *id > 0xFFFFFFFFll) {
      return UsageFailure("--table-id must be 1..4294967295 (0 means no table active)");
    }
    image_options.table_id = static_cast<uint32_t>(*id);
  }
  if (image_path && *image_path == *out_path) {
    return UsageFailure("-o names the input image: write the new image to a new file");
  }

  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table, ReadCsvArgument(files[0], ctx));
  VOLCOMP_TRY_ASSIGN(const metrology::DriftRecord record, metrology::ReadDriftCsv(table));
  std::optional<image::LoadedImage> input;
  if (image_path) {
    VOLCOMP_TRY_ASSIGN(image::LoadedImage loaded, image::ReadImageFile(*image_path));
    o.travel_mm = image::LinearAxisSpans(loaded.view());
    input.emplace(std::move(loaded));
  }
  VOLCOMP_TRY_ASSIGN(const builders::ThermalFit fit, builders::FitThermalModel(record, o));

  Output output;
  std::optional<thermal::ThermalModel> model;
  JsonValue image_data;
  if (input) {
    const table::TableView& v = input->view();
    Expected<thermal::ThermalModel> m = builders::ToThermalModel(fit, v.axes, v.axis_count);
    if (!m.ok()) return Fail(m.error().Prefixed(*image_path));
    model = *m;
    image_options.info["source"] = record.source;
    VOLCOMP_TRY_ASSIGN(const image::ThermalImage built,
                       image::WithThermalModel(*input, *image_path, *model, image_options));
    output.warnings = built.warnings;
    if (built.replaced) {
      output.warnings.push_back(*image_path + " had a THERMAL section: " + *out_path +
                                " has the new model in its place");
    }
    VOLCOMP_TRY(tools::WriteFileBytes(*out_path, built.bytes));
    VOLCOMP_TRY_ASSIGN(const image::LoadedImage result,
                       image::LoadedImage::FromBytes(built.bytes, *out_path));
    image_data = JsonValue::Object();
    image_data.Set("input", *image_path)
        .Set("output", *out_path)
        .Set("bytes", uint64_t{built.bytes.size()})
        .Set("table_id", uint64_t{result.view().table_id})
        .Set("crc32", tools::Hex32(result.view().crc32))
        .Set("channel_mask", uint64_t{model->channel_mask})
        .Set("replaced_thermal", built.replaced);
  }
  output.data = FitJson(fit, model ? &*model : nullptr);
  output.data.Set("command", "build thermal");
  output.data.Set("source", record.source);
  output.data.Set("sign", "correction = -drift");
  output.data.Set("image", std::move(image_data));
  output.text = BuildThermalText;
  return output;
}

}  // namespace

const Command& BuildThermalCommand() {
  static const Command kCommand{
      "build thermal",
      "fit the thermal model (offset and slope per channel and axis) to a drift test",
      "FILE|-",
      {{"--channels", nullptr, "NAME,...", nullptr, nullptr,
        "the channels of the model (default: every T_<name>_C column of the file)"},
       {"--reference-C", nullptr, "T|NAME=T,...", "°C", nullptr,
        "reference temperature of every channel, or per channel (default: its first reading)"},
       {"--max-condition", nullptr, "N", nullptr, "10000",
        "refuse a fit whose equilibrated normal equations have a larger condition number"},
       {"--image", nullptr, "IMAGE", nullptr, nullptr,
        "image whose GRID3 / AXIS1D sections the new image carries (with -o)"},
       {"--output", "-o", "IMAGE", nullptr, nullptr,
        "the new image: --image's sections and the fitted THERMAL section"},
       {"--table-id", nullptr, "N", nullptr, nullptr,
        "id of the new image, 1..4294967295 (default: --image's id)"},
       {"--json", nullptr, nullptr, nullptr, nullptr, "every value as JSON on stdout"}},
      RunBuildThermal,
      "Input: the drift test of `evaluate thermal`. Per axis, every reading after a point's first\n"
      "is one equation: -drift = sum_j offset_j*dT_j + slope_j*dT_j*(p - p0)/1000, dT_j the\n"
      "channel's change since that point's first reading; p0 = the mean of the points. The\n"
      "channel number in the image is the column's order among the T_ columns. Axes map to the\n"
      "image's by name (rotary axes have no thermal term). See docs/thermal.md \"The PC tool\"."};
  return kCommand;
}

}  // namespace volcomp::cli
