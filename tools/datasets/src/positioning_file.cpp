// One loader for positioning tests: CSV or Renishaw .rtl, recognised by content.
#include "volcomp/datasets/positioning_file.hpp"

#include "unit_check.hpp"
#include "volcomp/datasets/positioning_csv.hpp"
#include "volcomp/metrology/mean_deviations.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::datasets {

const char* PositioningFormatName(PositioningFormat format) {
  switch (format) {
    case PositioningFormat::kCsv:
      return "csv";
    case PositioningFormat::kRtl:
      return "rtl";
    case PositioningFormat::kAuto:
      break;
  }
  return "auto";
}

namespace {

// The readings' column unit when it is a micro-unit (µm, or µin: 0.0254 µm), else nullptr.
const MicroUnit* MicroUnitOf(const metrology::PositioningData& d) {
  if (d.kind != metrology::AxisKind::kLinear) return nullptr;
  if (d.column_scale == kMicrometre.um_per_unit) return &kMicrometre;
  if (d.column_scale == kMicroinch.um_per_unit) return &kMicroinch;
  return nullptr;  // mm, inches: whole units, not this check's business
}

// The unit plausibility check of every µm or µin column of a linear axis (unit_check.hpp).
Outcome CheckUnits(const PositioningFile& f) {
  const MicroUnit* unit = f.readings ? MicroUnitOf(*f.readings) : nullptr;
  if (unit) {
    std::vector<double> values;
    std::vector<std::size_t> lines;
    for (const auto& r : f.readings->readings) {
      values.push_back(r.deviation);
      lines.push_back(r.line);
    }
    const bool rtl = f.format == PositioningFormat::kRtl;
    const std::string fix =
        unit == &kMicrometre
            ? (rtl ? "an .rtl holds µm, so check the test in the laser software"
                   : "if they are mm, name the column deviation_mm")
            : (rtl ? "an .rtl read with --rtl-units in holds µin, so check the test in the laser "
                     "software"
                   : "if they are inches, name the column deviation_in");
    VOLCOMP_TRY(
        CheckMicroColumn(f.source, f.readings_line, f.readings->column, *unit, values, lines, fix));
  }
  if (f.means && !f.means->rotary) {
    // The means are held in µm; an inch file's columns are named and shown in their µin.
    const bool inch = f.means_in_inches;
    const MicroUnit& u = inch ? kMicroinch : kMicrometre;
    const char* fix = inch ? "if they are inches, multiply them by 1000000"
                           : "if they are mm, multiply them by 1000";
    VOLCOMP_TRY(CheckMicroColumn(f.source, f.readings_line,
                                 inch ? "dev_forward_uin" : "dev_forward_um", u,
                                 f.means->dev_forward, {}, fix));
    VOLCOMP_TRY(CheckMicroColumn(f.source, f.readings_line,
                                 inch ? "dev_reverse_uin" : "dev_reverse_um", u,
                                 f.means->dev_reverse, {}, fix));
  }
  return Outcome::Ok();
}

Expected<PositioningFile> ReadAnyFormat(const std::string& text,
                                        const std::string& source,
                                        const PositioningReadOptions& options) {
  const bool rtl = options.format == PositioningFormat::kRtl ||
                   (options.format == PositioningFormat::kAuto && LooksLikeRtl(text));
  if (!rtl) {
    Expected<PositioningFile> f = [&]() -> Expected<PositioningFile> {
      VOLCOMP_TRY_ASSIGN(const tools::CsvTable csv, tools::CsvTable::ReadString(text, source));
      return PositioningFileFromCsv(csv);
    }();
    if (!f.ok() && LooksLikeRtl(text)) {
      return Fail(f.error().code,
                  f.error().message +
                      " (the file looks like a Renishaw .rtl: --format rtl or auto reads it)");
    }
    return f;
  }
  VOLCOMP_TRY_ASSIGN(RtlTest test, ParseRtl(text, source, options.rtl));
  PositioningFile f;
  f.source = source;
  f.format = PositioningFormat::kRtl;
  f.rtl_units = options.rtl.units;
  f.conditions = std::move(test.conditions);
  f.readings = std::move(test.readings);
  f.readings_line = test.deviations_line;
  f.warnings = std::move(test.warnings);
  return f;
}

}  // namespace

Expected<PositioningFile> ReadPositioningText(const std::string& text,
                                              const std::string& source,
                                              const PositioningReadOptions& options) {
  VOLCOMP_TRY_ASSIGN(PositioningFile f, ReadAnyFormat(text, source, options));
  if (!options.accept_units) VOLCOMP_TRY(CheckUnits(f));
  return f;
}

Expected<PositioningFile> ReadPositioningFile(const std::string& path,
                                              const PositioningReadOptions& options) {
  VOLCOMP_TRY_ASSIGN(const std::string text, tools::ReadTextFile(path));
  return ReadPositioningText(text, path, options);
}

Expected<model::PositioningData> PositioningMeans(const PositioningFile& file,
                                                  const metrology::GroupingOptions& grouping) {
  model::PositioningData d;
  if (file.means) {
    d = *file.means;
  } else {
    if (!file.readings) return Fail(Error::kInputInvalid, file.source + ": no readings");
    VOLCOMP_TRY_ASSIGN(
        const metrology::MeanDeviations m,
        metrology::MeanDeviationsFromReadings(*file.readings, grouping, file.readings_line));
    d.rotary = m.kind == metrology::AxisKind::kRotary;
    d.position = m.target;
    d.dev_forward = m.mean_up;
    d.dev_reverse = m.mean_down;
    d.warnings = m.warnings;
    if (d.position.size() < 2) {
      return Fail(Error::kInputInvalid,
                  file.source + ":" + std::to_string(file.readings_line) +
                      ": a positioning test needs at least 2 target positions");
    }
  }
  d.warnings.insert(d.warnings.begin(), file.warnings.begin(), file.warnings.end());
  return d;
}

}  // namespace volcomp::datasets
