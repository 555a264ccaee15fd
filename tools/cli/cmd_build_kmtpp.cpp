// `volcomp build kmtpp`: a GRID3 image by КМТПП, the quasi-differential method on parametric-error
// tables (dissertation ch. 4). Calibration (origin r01, axis vectors) from laser-tracker lines,
// angular errors from the model's axis tables. Default: the smooth final step (traced point); the
// printed, discontinuous form with --dissertation. See docs/table-builders.md.
#include <array>
#include <iostream>
#include <map>
#include <string>

#include "commands.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/model/io.hpp"
#include "volcomp/model/kmtpp.hpp"
#include "volcomp/model/tracker.hpp"

namespace volcomp::tools {

int RunBuildKmtpp(Args& args) {
  const model::Model m = model::cli::ParseModelOptions(args);
  const auto tracker_file = args.value("--tracker");
  const std::string tracker_builtin = args.value("--tracker-builtin").value_or("s500-315");
  model::TrackerData data;
  if (tracker_file) {
    data = model::LoadTrackerCsv(*tracker_file);
  } else if (tracker_builtin == "s500-315") {
    data = model::S500Tracker315();
  } else if (tracker_builtin == "s500-240") {
    data = model::S500Tracker240();
  } else {
    throw UsageError("--tracker-builtin must be s500-315 or s500-240");
  }
  model::TrackerOptions topt;
  const std::string cosines = args.value("--cosines").value_or("signed");
  if (cosines == "signed") {
    topt.cosines = model::CosineSource::kSigned;
  } else if (cosines == "printed") {
    topt.cosines = model::CosineSource::kPrinted;
  } else {
    throw UsageError("--cosines must be signed or printed (unit axis vectors)");
  }
  int interval = 1;
  if (auto i = args.integer("--calibration-interval")) {
    if (*i < 0 || *i > 1000) throw UsageError("--calibration-interval out of range");
    interval = static_cast<int>(*i);
  }
  model::KmtppOptions opt;
  const bool dissertation = args.flag("--dissertation");
  if (dissertation) opt = model::KmtppDissertationOptions(opt.gain, opt.step);
  if (auto k = args.number("--gain")) opt.gain = *k;
  if (auto l = args.number("--step")) opt.step = *l;
  if (auto f = args.value("--final-step")) {
    if (*f == "traced") {
      opt.final_step = model::KmtppFinalStep::kTracedPoint;
    } else if (*f == "node") {
      opt.final_step = model::KmtppFinalStep::kGridNode;
    } else {
      throw UsageError("--final-step must be traced or node");
    }
  }
  if (auto s = args.value("--sum")) {
    if (*s == "matrix") {
      opt.sum_form = model::KmtppSumForm::kMatrix;
    } else if (*s == "listing") {
      opt.sum_form = model::KmtppSumForm::kListing;
    } else {
      throw UsageError("--sum must be matrix or listing");
    }
  }
  if (auto r = args.value("--index")) {
    if (*r == "round") {
      opt.index_rule = model::KmtppIndexRule::kRound;
    } else if (*r == "floor") {
      opt.index_rule = model::KmtppIndexRule::kFloor;
    } else {
      throw UsageError("--index must be round or floor");
    }
  }
  if (!(opt.gain * opt.step > 0 && opt.gain * opt.step < 2)) {
    throw UsageError("--gain times --step must lie in (0, 2)");
  }
  std::array<model::AxisErrorTable, 3> tables = m.axes;
  if (auto refine = args.number("--refine-mm")) {
    if (!(*refine > 0)) throw UsageError("--refine-mm must be positive");
    for (auto& t : tables) t = t.Resampled(*refine, t.max_mm());
  }
  const bool allow_jumps = args.flag("--allow-discontinuous");
  if (opt.final_step == model::KmtppFinalStep::kGridNode && !allow_jumps) {
    throw UsageError(
        "the printed final step (grid node) jumps by up to half a table step wherever the node "
        "changes; a trilinear grid cannot represent it. Use the default traced-point step, or "
        "pass --allow-discontinuous");
  }
  std::array<double, 3> lo, hi, natural;
  for (std::size_t a = 0; a < 3; ++a) {
    if (!(tables[a].uniform_spacing_mm() > 0)) {
      throw InputError(std::string("КМТПП needs equally spaced tables; axis ") + "XYZ"[a] +
                       " is not (use --refine-mm)");
    }
    lo[a] = tables[a].min_mm();
    hi[a] = tables[a].max_mm();
    natural[a] = tables[a].uniform_spacing_mm();
  }
  const model::KmtppCalibration cal = [&]() {
    try {
      return model::KmtppCalibrationFromTracker(model::TrackerModel(data, topt), interval);
    } catch (const std::invalid_argument& e) {
      throw InputError(data.name + ": " + e.what());
    }
  }();
  model::cli::GridCommand cmd = model::cli::ParseGridCommand(args, lo, hi, natural);
  args.finish();

  const model::InverseMap inverse = [&](const model::Vec3& t) {
    return model::Kmtpp(tables, cal, opt, t).command_mm;
  };
  const std::map<std::string, std::string> info = {
      {"builder", "volcomp build kmtpp"},
      {"tables", m.name},
      {"calibration", data.name + ", interval " + std::to_string(interval) + ", " + cosines},
      {"law", "K=" + std::to_string(opt.gain) + " l=" + std::to_string(opt.step)},
      {"final_step", opt.final_step == model::KmtppFinalStep::kTracedPoint ? "traced point"
                                                                           : "grid node (printed)"},
      {"sum", opt.sum_form == model::KmtppSumForm::kMatrix ? "matrix (4.9)" : "listing (dot)"},
  };
  if (!cmd.json) std::cout << "volcomp build kmtpp\n";
  return model::cli::RunGridBuild(cmd, inverse, nullptr, info, std::cout);
}

}  // namespace volcomp::tools
