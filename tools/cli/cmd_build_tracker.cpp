// `volcomp build tracker`: a GRID3 image from laser-tracker axis lines by the dissertation's
// tangential methods (ch. 2): static, interval or quasi-differential, with printed (sign-dropped),
// signed or scaled direction vectors; or from tracker readings at every node of a lattice
// (--lattice, model/tracker_lattice.hpp). See docs/table-builders.md.
#include <optional>
#include <string>

#include "build_options.hpp"
#include "choice_option.hpp"
#include "commands.hpp"
#include "grid_build.hpp"
#include "option_groups.hpp"
#include "volcomp/builders/image_grid.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/datasets/tracker_csv.hpp"
#include "volcomp/datasets/tracker_lattice_file.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp::cli {
namespace {

constexpr const char* kBuilder = "volcomp build tracker";

// --format, --nominals, --sa-units, --sa-name-fields: how the lattice file is read.
Expected<datasets::LatticeFileOptions> LatticeFileOptions(Args& args) {
  datasets::LatticeFileOptions o;
  using datasets::LatticeFormat;
  VOLCOMP_TRY_ASSIGN(o.format,
                     ParseChoice<LatticeFormat>("--format", args.Value("--format").value_or("auto"),
                                                {{"auto", LatticeFormat::kAuto},
                                                 {"csv", LatticeFormat::kCsv},
                                                 {"sa-ascii", LatticeFormat::kSaAscii},
                                                 {"sa-xml", LatticeFormat::kSaXml}}));
  if (const auto unit = args.Value("--sa-units")) {
    VOLCOMP_TRY_ASSIGN(o.sa_unit,
                       ParseChoice<datasets::SaUnit>("--sa-units", *unit,
                                                     {{"mm", datasets::SaUnit::kMillimetre},
                                                      {"in", datasets::SaUnit::kInch},
                                                      {"m", datasets::SaUnit::kMetre}}));
  }
  o.nominals_path = args.Value("--nominals");
  const auto name_fields = args.Integer("--sa-name-fields");
  VOLCOMP_TRY(args.status());
  if (name_fields) {
    if (*name_fields < 1 || *name_fields > 3) {
      return UsageFailure("--sa-name-fields " + std::to_string(*name_fields) +
                          ": a point name has 1 to 3 parts (Collection Group Target)");
    }
    o.sa_name_fields = static_cast<int>(*name_fields);
  }
  return o;
}

// --lattice FILE [--through IMAGE]: the lattice's exact inverse (composed with the GRID3 of the
// table that was in force while it was measured).
Expected<Output> RunBuildTrackerLattice(Args& args, const std::string& path) {
  const auto through = args.Value("--through");
  VOLCOMP_TRY_ASSIGN(const datasets::LatticeFileOptions options, LatticeFileOptions(args));
  VOLCOMP_TRY_ASSIGN(datasets::LoadedLattice loaded,
                     datasets::LoadTrackerLatticeFile(path, options));
  auto lattice = model::TrackerLattice::Create(std::move(loaded.data));
  if (!lattice.ok()) return Fail(Error::kInputInvalid, path + ": " + lattice.error().message);
  builders::GridSource source;
  if (through) {
    VOLCOMP_TRY_ASSIGN(const image::LoadedImage in_force, image::ReadImageFile(*through));
    VOLCOMP_TRY_ASSIGN(const model::CorrectionGrid grid, builders::GridOfImage(in_force, *through));
    source = builders::TrackerLatticeThroughGridSource(*lattice, grid);
    source.info.emplace("table_in_force", *through);
  } else {
    source = builders::TrackerLatticeGridSource(*lattice);
  }
  source.info.emplace("lattice_format", datasets::LatticeFormatName(loaded.format));
  if (options.nominals_path) source.info.emplace("nominals", *options.nominals_path);
  VOLCOMP_TRY_ASSIGN(const GridCommand command, ParseGridCommand(args, source));
  VOLCOMP_TRY(args.Finish());
  return RunGridBuild(command, source, kBuilder);
}

// The tracker lines: --points FILE or --builtin NAME.
Expected<model::TrackerData> TrackerLines(const std::optional<std::string>& points,
                                          const std::optional<std::string>& builtin) {
  if (!builtin) return datasets::LoadTrackerCsv(*points);
  if (auto data = datasets::S500TrackerNamed(*builtin)) return *data;
  return UsageFailure("--builtin must be s500-315 or s500-240");
}

Expected<Output> RunBuildTracker(Args& args, Context&) {
  const auto points = args.Value("--points");
  const auto builtin = args.Value("--builtin");
  const auto lattice = args.Value("--lattice");
  if (points.has_value() + builtin.has_value() + lattice.has_value() != 1) {
    return UsageFailure("give one of --points FILE, --builtin s500-315|s500-240 or --lattice FILE");
  }
  if (lattice) return RunBuildTrackerLattice(args, *lattice);
  VOLCOMP_TRY_ASSIGN(const model::TrackerData data, TrackerLines(points, builtin));
  const std::string method = args.Value("--method").value_or("quasi-differential");
  if (method != "static" && method != "interval" && method != "quasi-differential") {
    return UsageFailure("--method must be static, interval or quasi-differential");
  }
  model::TrackerOptions opt;
  const bool integrating = method == "quasi-differential";
  const std::string cosines = args.Value("--cosines").value_or(integrating ? "scaled" : "signed");
  if (cosines == "scaled" && !integrating) {
    return UsageFailure("--cosines scaled needs the quasi-differential method: the " + method +
                        " method would stretch one cell's step length over the whole travel");
  }
  VOLCOMP_TRY_ASSIGN(opt.cosines,
                     ParseChoice<model::CosineSource>("--cosines", cosines,
                                                      {{"printed", model::CosineSource::kPrinted},
                                                       {"signed", model::CosineSource::kSigned},
                                                       {"scaled", model::CosineSource::kScaled}}));
  VOLCOMP_TRY_ASSIGN(
      opt.origin,
      ParseChoice<model::OriginSource>(
          "--origin",
          args.Value("--origin").value_or(cosines == "scaled" ? "measured" : "extrapolated"),
          {{"measured", model::OriginSource::kMeasured},
           {"extrapolated", model::OriginSource::kExtrapolated}}));
  const auto interval = args.Integer("--static-interval");
  VOLCOMP_TRY(args.status());
  if (interval) {
    if (*interval < 0 || *interval > 1000) return UsageFailure("--static-interval out of range");
    opt.static_interval = static_cast<int>(*interval);
  }
  const bool appendix_form = args.Flag("--appendix-form");
  const bool allow_jumps = args.Flag("--allow-discontinuous");
  if (method == "interval" && !allow_jumps) {
    return UsageFailure(
        "the interval method jumps by tens of µm at every cell border (a trilinear grid would "
        "smear the jumps); use quasi-differential, or pass --allow-discontinuous");
  }
  const Expected<model::TrackerModel> tm = model::TrackerModel::Create(data, opt);
  if (!tm.ok()) return Fail(Error::kInputInvalid, data.name + ": " + tm.error().message);
  const builders::TrackerMethod m = method == "static" ? builders::TrackerMethod::kStatic
                                    : method == "interval"
                                        ? builders::TrackerMethod::kInterval
                                        : builders::TrackerMethod::kQuasiDifferential;
  const builders::GridSource source = builders::TrackerLinesGridSource(data, *tm, m, appendix_form);
  VOLCOMP_TRY_ASSIGN(const GridCommand command, ParseGridCommand(args, source));
  VOLCOMP_TRY(args.Finish());
  return RunGridBuild(command, source, kBuilder);
}

}  // namespace

const Command& BuildTrackerCommand() {
  static const Command kCommand{
      "build tracker",
      "GRID3 image from laser-tracker axis lines or a lattice (dissertation ch. 2 methods)",
      "",
      Join({{{"--points", nullptr, "FILE", nullptr, nullptr,
              "tracker lines CSV (or --builtin, or --lattice)"},
             {"--builtin", nullptr, "s500-315|s500-240", nullptr, nullptr,
              "the dissertation's tracker lines"},
             {"--lattice", nullptr, "FILE", nullptr, nullptr,
              "tracker readings at every lattice node: CSV (x_cmd_mm..z_cmd_mm, x_mm..z_mm) or a "
              "SpatialAnalyzer export (XML NOMINAL/ACTUAL pairs, or ASCII with --nominals)"},
             {"--format", nullptr, "auto|csv|sa-ascii|sa-xml", nullptr, "auto",
              "the lattice file's format (auto: recognised by content)"},
             {"--nominals", nullptr, "FILE", nullptr, nullptr,
              "commanded nodes for an SA ASCII lattice, paired BY NAME with its measured points "
              "(SA ASCII, or CSV name,x_cmd_mm,y_cmd_mm,z_cmd_mm); a name in one file only is "
              "refused"},
             {"--sa-units", nullptr, "mm|in|m", nullptr, nullptr,
              "the unit of the SA working frame (SA files only; default mm)"},
             {"--sa-name-fields", nullptr, "N", nullptr, nullptr,
              "name parts (1..3) before x y z in SA ASCII lines (default: the non-numbers)"},
             {"--through", nullptr, "IMAGE", nullptr, nullptr,
              "the table in force while the lattice was measured (composed with it)"},
             {"--method", nullptr, "static|interval|quasi-differential", nullptr,
              "quasi-differential", "correction method"},
             {"--cosines", nullptr, "printed|signed|scaled", nullptr, nullptr,
              "axis vectors (default: scaled for quasi-differential, else signed)"},
             {"--origin", nullptr, "measured|extrapolated", nullptr, nullptr,
              "r01 (default: measured with scaled vectors, else extrapolated)"},
             {"--static-interval", nullptr, "N", nullptr, nullptr,
              "interval of the static calibration matrix (default 1)"},
             {"--appendix-form", nullptr, nullptr, nullptr, nullptr,
              "the printed algorithm instead of the exact inverse"},
             {"--allow-discontinuous", nullptr, nullptr, nullptr, nullptr,
              "allow a method that jumps at cell borders"}},
            GridOptions()}),
      RunBuildTracker,
      GridNotes()};
  return kCommand;
}

}  // namespace volcomp::cli
