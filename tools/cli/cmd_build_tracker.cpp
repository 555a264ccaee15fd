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
#include "volcomp/image/image_reader.hpp"

namespace volcomp::cli {
namespace {

constexpr const char* kBuilder = "volcomp build tracker";

// --lattice FILE [--through IMAGE]: the lattice's exact inverse (composed with the GRID3 of the
// table that was in force while it was measured).
Expected<Output> RunBuildTrackerLattice(Args& args, const std::string& path) {
  const auto through = args.Value("--through");
  VOLCOMP_TRY_ASSIGN(model::TrackerLatticeData data, datasets::LoadTrackerLatticeCsv(path));
  auto lattice = model::TrackerLattice::Create(std::move(data));
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
              "tracker readings at every lattice node (x_cmd_mm..z_cmd_mm, x_mm..z_mm)"},
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
