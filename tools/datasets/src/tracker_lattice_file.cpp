// The lattice file in any of its formats (tracker_lattice_file.hpp).
#include "volcomp/datasets/tracker_lattice_file.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "volcomp/datasets/tracker_csv.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp::datasets {
namespace {

SaUnit Unit(const LatticeFileOptions& options) {
  return options.sa_unit.value_or(SaUnit::kMillimetre);
}

LatticeFormat Recognised(const std::string& text) {
  if (LooksLikeSaXml(text)) return LatticeFormat::kSaXml;
  if (LooksLikeSaAscii(text)) return LatticeFormat::kSaAscii;
  return LatticeFormat::kCsv;
}

std::string Mm(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The nominal points of --nominals: SA ASCII, or a CSV of name, x_cmd_mm, y_cmd_mm, z_cmd_mm.
Expected<std::vector<SaPoint>> Nominals(const std::string& path,
                                        const LatticeFileOptions& options) {
  VOLCOMP_TRY_ASSIGN(const std::string text, tools::ReadTextFile(path));
  if (LooksLikeSaAscii(text)) {
    return SaPointsFromAscii(text, path, Unit(options), options.sa_name_fields);
  }
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable csv, tools::CsvTable::ReadString(text, path));
  std::vector<SaPoint> points;
  std::map<std::string, std::size_t> line_of;
  for (const tools::CsvRow& r : csv.rows()) {
    tools::CsvFields f(r);
    SaPoint p{f.Text("name"),
              {f.Number("x_cmd_mm"), f.Number("y_cmd_mm"), f.Number("z_cmd_mm")},
              r.line()};
    VOLCOMP_TRY(f.status());
    const auto first = line_of.emplace(p.name, p.line);
    if (!first.second) {
      return Fail(csv.LineFailure(r.line(), "point \"" + p.name + "\" given twice (first on line " +
                                                std::to_string(first.first->second) + ")"));
    }
    points.push_back(std::move(p));
  }
  return points;
}

// Measured points paired by name with the nominals; every name in both files.
Expected<std::vector<TrackerLatticeReading>> PairedByName(const std::string& path,
                                                          const std::vector<SaPoint>& measured,
                                                          const std::string& nominals_path,
                                                          const std::vector<SaPoint>& nominals) {
  std::map<std::string, const SaPoint*> nominal_of;
  for (const SaPoint& p : nominals) nominal_of.emplace(p.name, &p);
  std::map<std::string, std::size_t> measured_line;
  std::vector<TrackerLatticeReading> readings;
  for (const SaPoint& p : measured) {
    const auto n = nominal_of.find(p.name);
    if (n == nominal_of.end()) {
      return Fail(Error::kInputInvalid, path + ":" + std::to_string(p.line) + ": point \"" +
                                            p.name + "\" has no nominal in " + nominals_path);
    }
    measured_line.emplace(p.name, p.line);
    readings.push_back({n->second->position_mm, p.position_mm, p.line});
  }
  for (const SaPoint& n : nominals) {
    if (measured_line.count(n.name) == 0) {
      return Fail(Error::kInputInvalid, nominals_path + ":" + std::to_string(n.line) +
                                            ": nominal point \"" + n.name +
                                            "\" was not measured (not in " + path + ")");
    }
  }
  return readings;
}

Outcome CheckPlausible(const std::string& path, const std::vector<TrackerLatticeReading>& r) {
  double span = 0.0;
  for (int a = 0; a < 3; ++a) {
    const auto [lo, hi] = std::minmax_element(
        r.begin(), r.end(), [a](const TrackerLatticeReading& p, const TrackerLatticeReading& q) {
          return p.command_mm[a] < q.command_mm[a];
        });
    if (lo != r.end()) span = std::max(span, hi->command_mm[a] - lo->command_mm[a]);
  }
  if (span < kSaMinimumSpan_mm) {
    return Fail(Error::kInputInvalid,
                path + ": the nominal points span only " + Mm(span) + " mm (less than " +
                    Mm(kSaMinimumSpan_mm) +
                    " mm along every axis): is the frame in metres or inches (--sa-units m|in)?");
  }
  for (const TrackerLatticeReading& p : r) {
    const double d = Norm(p.reading_mm - p.command_mm);
    if (d > kSaMaximumDeviation_mm) {
      return Fail(Error::kInputInvalid,
                  path + ":" + std::to_string(p.line) + ": the reading lies " + Mm(d) +
                      " mm from its nominal (more than " + Mm(kSaMaximumDeviation_mm) +
                      " mm): a wrong pairing, or nominals and readings in different units?");
    }
  }
  return Outcome::Ok();
}

// The lattice of `text` read as `format` (not kAuto).
Expected<LoadedLattice> ReadLattice(const std::string& path,
                                    const std::string& text,
                                    LatticeFormat format,
                                    const LatticeFileOptions& options) {
  LoadedLattice out;
  out.format = format;
  const std::string name = LatticeFormatName(out.format);
  if (out.format != LatticeFormat::kSaAscii && options.nominals_path) {
    return Fail(Error::kUsage,
                path + " is read as " + name +
                    ", which carries its own commanded nodes: --nominals pairs an SA ASCII export "
                    "only");
  }
  if (out.format == LatticeFormat::kCsv) {
    if (options.sa_name_fields || options.sa_unit) {
      return Fail(Error::kUsage, path + " is read as csv (in mm by its column names): " +
                                     (options.sa_unit ? "--sa-units" : "--sa-name-fields") +
                                     " is for SA files");
    }
    VOLCOMP_TRY_ASSIGN(const tools::CsvTable csv, tools::CsvTable::ReadString(text, path));
    VOLCOMP_TRY_ASSIGN(out.data, TrackerLatticeFromCsv(csv));
    return out;
  }
  std::vector<TrackerLatticeReading> readings;
  if (out.format == LatticeFormat::kSaXml) {
    VOLCOMP_TRY_ASSIGN(const std::vector<SaPointPair> pairs,
                       SaPairsFromXml(text, path, Unit(options)));
    for (const SaPointPair& p : pairs) readings.push_back({p.nominal_mm, p.actual_mm, p.line});
  } else {
    if (!options.nominals_path) {
      return Fail(Error::kUsage,
                  path +
                      " is an SA ASCII export, which holds only the measured points: give "
                      "--nominals FILE with the commanded point of every name");
    }
    VOLCOMP_TRY_ASSIGN(const std::vector<SaPoint> measured,
                       SaPointsFromAscii(text, path, Unit(options), options.sa_name_fields));
    VOLCOMP_TRY_ASSIGN(const std::vector<SaPoint> nominals,
                       Nominals(*options.nominals_path, options));
    VOLCOMP_TRY_ASSIGN(readings, PairedByName(path, measured, *options.nominals_path, nominals));
  }
  VOLCOMP_TRY(CheckPlausible(path, readings));
  VOLCOMP_TRY_ASSIGN(out.data, TrackerLatticeFromReadings(path, 0, readings));
  return out;
}

}  // namespace

const char* LatticeFormatName(LatticeFormat format) {
  switch (format) {
    case LatticeFormat::kCsv:
      return "csv";
    case LatticeFormat::kSaAscii:
      return "sa-ascii";
    case LatticeFormat::kSaXml:
      return "sa-xml";
    case LatticeFormat::kAuto:
      break;
  }
  return "auto";
}

Expected<LoadedLattice> LoadTrackerLatticeFile(const std::string& path,
                                               const LatticeFileOptions& options) {
  VOLCOMP_TRY_ASSIGN(const std::string text, tools::ReadTextFile(path));
  const LatticeFormat recognised = Recognised(text);
  const LatticeFormat format = options.format == LatticeFormat::kAuto ? recognised : options.format;
  Expected<LoadedLattice> out = ReadLattice(path, text, format, options);
  if (!out.ok() && out.error().code == Error::kInputInvalid && format != recognised) {
    return Fail(Error::kInputInvalid, out.error().message + " (read as " +
                                          LatticeFormatName(format) + "; the file looks like " +
                                          LatticeFormatName(recognised) + ": --format auto)");
  }
  return out;
}

}  // namespace volcomp::datasets
