// `volcomp build kmtpp`: a GRID3 image by КМТПП, the quasi-differential method on parametric-error
// tables (dissertation ch. 4). Calibration (origin r01, axis vectors) from laser-tracker lines,
// angular errors from the model's axis tables. Default: the smooth final step (traced point); the
// printed, discontinuous form with --dissertation. See docs/table-builders.md.
#include <array>
#include <string>

#include "build_options.hpp"
#include "choice_option.hpp"
#include "commands.hpp"
#include "grid_build.hpp"
#include "option_groups.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/datasets/tracker_csv.hpp"
#include "volcomp/model/kmtpp.hpp"

namespace volcomp::cli {
namespace {

// The calibration's tracker lines: --tracker FILE, else --tracker-builtin NAME.
Expected<model::TrackerData> CalibrationLines(Args& args) {
  const auto file = args.Value("--tracker");
  const std::string builtin = args.Value("--tracker-builtin").value_or("s500-315");
  if (file) return datasets::LoadTrackerCsv(*file);
  if (auto data = datasets::S500TrackerNamed(builtin)) return *data;
  return UsageFailure("--tracker-builtin must be s500-315 or s500-240");
}

// --dissertation, --gain, --step, --final-step, --sum, --index.
Expected<model::KmtppOptions> ParseKmtppOptions(Args& args) {
  model::KmtppOptions opt;
  if (args.Flag("--dissertation")) opt = model::KmtppDissertationOptions(opt.gain, opt.step);
  const auto gain = args.Number("--gain");
  const auto step = args.Number("--step");
  VOLCOMP_TRY(args.status());
  if (gain) opt.gain = *gain;
  if (step) opt.step = *step;
  if (auto f = args.Value("--final-step")) {
    VOLCOMP_TRY_ASSIGN(opt.final_step, ParseChoice<model::KmtppFinalStep>(
                                           "--final-step", *f,
                                           {{"traced", model::KmtppFinalStep::kTracedPoint},
                                            {"node", model::KmtppFinalStep::kGridNode}}));
  }
  if (auto s = args.Value("--sum")) {
    VOLCOMP_TRY_ASSIGN(opt.sum_form, ParseChoice<model::KmtppSumForm>(
                                         "--sum", *s,
                                         {{"matrix", model::KmtppSumForm::kMatrix},
                                          {"listing", model::KmtppSumForm::kListing}}));
  }
  if (auto r = args.Value("--index")) {
    VOLCOMP_TRY_ASSIGN(opt.index_rule, ParseChoice<model::KmtppIndexRule>(
                                           "--index", *r,
                                           {{"round", model::KmtppIndexRule::kRound},
                                            {"floor", model::KmtppIndexRule::kFloor}}));
  }
  if (!(opt.gain * opt.step > 0 && opt.gain * opt.step < 2)) {
    return UsageFailure("--gain times --step must lie in (0, 2)");
  }
  return opt;
}

Expected<Output> RunBuildKmtpp(Args& args, Context& ctx) {
  ModelSource model_source;
  VOLCOMP_TRY_ASSIGN(const model::Model m, ParseModelOptions(args, std::nullopt, &model_source));
  for (const std::string& w : model_source.warnings) ctx.err << "warning: " << w << "\n";
  VOLCOMP_TRY_ASSIGN(const model::TrackerData data, CalibrationLines(args));
  model::TrackerOptions topt;
  const std::string cosines = args.Value("--cosines").value_or("signed");
  VOLCOMP_TRY_ASSIGN(topt.cosines,
                     ParseChoice<model::CosineSource>("--cosines", cosines,
                                                      {{"signed", model::CosineSource::kSigned},
                                                       {"printed", model::CosineSource::kPrinted}},
                                                      "unit axis vectors"));
  const auto interval_option = args.Integer("--calibration-interval");
  VOLCOMP_TRY(args.status());
  int interval = 1;
  if (interval_option) {
    if (*interval_option < 0 || *interval_option > 1000) {
      return UsageFailure("--calibration-interval out of range");
    }
    interval = static_cast<int>(*interval_option);
  }
  VOLCOMP_TRY_ASSIGN(const model::KmtppOptions opt, ParseKmtppOptions(args));
  std::array<model::AxisErrorTable, 3> tables = m.axes;
  const auto refine = args.Number("--refine-mm");
  VOLCOMP_TRY(args.status());
  if (refine) {
    if (!(*refine > 0)) return UsageFailure("--refine-mm must be positive");
    for (auto& t : tables) {
      VOLCOMP_TRY_ASSIGN(t, t.Resampled(*refine, t.max_mm()));
    }
  }
  const bool allow_jumps = args.Flag("--allow-discontinuous");
  if (opt.final_step == model::KmtppFinalStep::kGridNode && !allow_jumps) {
    return UsageFailure(
        "the printed final step (grid node) jumps by up to half a table step wherever the node "
        "changes; a trilinear grid cannot represent it. Use the default traced-point step, or "
        "pass --allow-discontinuous");
  }
  const Expected<model::TrackerModel> tracker = model::TrackerModel::Create(data, topt);
  if (!tracker.ok()) {
    return Fail(Error::kInputInvalid, data.name + ": " + tracker.error().message);
  }
  const model::KmtppCalibration cal = model::KmtppCalibrationFromTracker(*tracker, interval);
  Expected<builders::GridSource> source = builders::KmtppGridSource(tables, cal, opt);
  if (!source.ok()) {
    return Fail(Error::kInputInvalid, source.error().message + " (use --refine-mm)");
  }
  source->info.emplace("tables", m.name);
  source->info.emplace("calibration",
                       data.name + ", interval " + std::to_string(interval) + ", " + cosines);
  VOLCOMP_TRY_ASSIGN(const GridCommand command, ParseGridCommand(args, *source));
  VOLCOMP_TRY(args.Finish());
  return RunGridBuild(command, *source, "volcomp build kmtpp");
}

}  // namespace

const Command& BuildKmtppCommand() {
  static const Command kCommand{
      "build kmtpp",
      "GRID3 image by the КМТПП method (dissertation ch. 4)",
      "",
      Join(
          {ModelOptions(),
           {{"--tracker", nullptr, "FILE", nullptr, nullptr, "tracker lines for the calibration"},
            {"--tracker-builtin", nullptr, "s500-315|s500-240", nullptr, "s500-315",
             "built-in tracker lines (without --tracker)"},
            {"--cosines", nullptr, "signed|printed", nullptr, "signed", "calibration vectors"},
            {"--calibration-interval", nullptr, "N", nullptr, "1", "calibration interval"},
            {"--gain", nullptr, "K", nullptr, nullptr, "K (default 1.5); K·l in (0, 2)"},
            {"--step", nullptr, "L", nullptr, nullptr, "l, model-time step (default 0.1)"},
            {"--final-step", nullptr, "traced|node", nullptr, nullptr,
             "final step base (default traced; node with --dissertation)"},
            {"--sum", nullptr, "matrix|listing", nullptr, nullptr,
             "S update (default matrix; listing with --dissertation)"},
            {"--index", nullptr, "round|floor", nullptr, nullptr, "table row rule (default round)"},
            {"--dissertation", nullptr, nullptr, nullptr, nullptr, "the printed variant"},
            {"--refine-mm", nullptr, "H", "mm", nullptr, "resample the tables every H"},
            {"--allow-discontinuous", nullptr, nullptr, nullptr, nullptr,
             "allow the printed final step, which jumps"}},
           GridOptions()}),
      RunBuildKmtpp,
      GridNotes()};
  return kCommand;
}

}  // namespace volcomp::cli
