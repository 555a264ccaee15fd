// `volcomp build tracker`: a GRID3 image from laser-tracker axis lines by the dissertation's
// tangential methods (ch. 2): static, interval or quasi-differential, with printed (sign-dropped),
// signed or scaled direction vectors; or from tracker readings at every node of a lattice
// (--lattice, tracker_lattice.hpp). See docs/table-builders.md.
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/model/grid_source.hpp"
#include "volcomp/model/image_grid.hpp"
#include "volcomp/model/io.hpp"
#include "volcomp/model/tracker.hpp"
#include "volcomp/model/tracker_lattice.hpp"

namespace volcomp::tools {

namespace {

// --lattice FILE [--through IMAGE]: the lattice's exact inverse (composed with the GRID3 of the
// table that was in force while it was measured).
int RunBuildTrackerLattice(Args& args, const std::string& path) {
  const auto through = args.value("--through");
  const model::TrackerLatticeData data = model::LoadTrackerLatticeCsv(path);
  const model::TrackerLattice lattice = [&]() {
    try {
      return model::TrackerLattice(data);
    } catch (const std::invalid_argument& e) {
      throw InputError(path + ": " + e.what());
    }
  }();
  const model::GridSource source =
      through ? model::TrackerLatticeThroughGridSource(
                    lattice, model::GridOfImage(image::LoadImageFile(*through), *through))
              : model::TrackerLatticeGridSource(lattice);
  model::cli::GridCommand cmd =
      model::cli::ParseGridCommand(args, source.min_mm, source.max_mm, source.natural_spacing_mm);
  args.finish();
  std::map<std::string, std::string> info = source.info;
  info.emplace("builder", "volcomp build tracker");
  if (through) info.emplace("table_in_force", *through);
  if (!cmd.json) std::cout << "volcomp build tracker\n";
  return model::cli::RunGridBuild(cmd, source.inverse, source.forward_or_null(), info, std::cout);
}

}  // namespace

int RunBuildTracker(Args& args) {
  const auto points = args.value("--points");
  const auto builtin = args.value("--builtin");
  const auto lattice = args.value("--lattice");
  if (points.has_value() + builtin.has_value() + lattice.has_value() != 1) {
    throw UsageError("give one of --points FILE, --builtin s500-315|s500-240 or --lattice FILE");
  }
  if (lattice) return RunBuildTrackerLattice(args, *lattice);
  model::TrackerData data;
  if (builtin) {
    if (*builtin == "s500-315") {
      data = model::S500Tracker315();
    } else if (*builtin == "s500-240") {
      data = model::S500Tracker240();
    } else {
      throw UsageError("--builtin must be s500-315 or s500-240");
    }
  } else {
    data = model::LoadTrackerCsv(*points);
  }
  const std::string method = args.value("--method").value_or("quasi-differential");
  if (method != "static" && method != "interval" && method != "quasi-differential") {
    throw UsageError("--method must be static, interval or quasi-differential");
  }
  model::TrackerOptions opt;
  const bool integrating = method == "quasi-differential";
  const std::string cosines = args.value("--cosines").value_or(integrating ? "scaled" : "signed");
  if (cosines == "scaled" && !integrating) {
    throw UsageError("--cosines scaled needs the quasi-differential method: the " + method +
                     " method would stretch one cell's step length over the whole travel");
  }
  if (cosines == "printed") {
    opt.cosines = model::CosineSource::kPrinted;
  } else if (cosines == "signed") {
    opt.cosines = model::CosineSource::kSigned;
  } else if (cosines == "scaled") {
    opt.cosines = model::CosineSource::kScaled;
  } else {
    throw UsageError("--cosines must be printed, signed or scaled");
  }
  const std::string origin =
      args.value("--origin").value_or(cosines == "scaled" ? "measured" : "extrapolated");
  if (origin == "measured") {
    opt.origin = model::OriginSource::kMeasured;
  } else if (origin == "extrapolated") {
    opt.origin = model::OriginSource::kExtrapolated;
  } else {
    throw UsageError("--origin must be measured or extrapolated");
  }
  if (auto s = args.integer("--static-interval")) {
    if (*s < 0 || *s > 1000) throw UsageError("--static-interval out of range");
    opt.static_interval = static_cast<int>(*s);
  }
  const bool appendix_form = args.flag("--appendix-form");
  const bool allow_jumps = args.flag("--allow-discontinuous");
  if (method == "interval" && !allow_jumps) {
    throw UsageError(
        "the interval method jumps by tens of µm at every cell border (a trilinear grid would "
        "smear the jumps); use quasi-differential, or pass --allow-discontinuous");
  }
  model::TrackerModel tm = [&]() {
    try {
      return model::TrackerModel(data, opt);
    } catch (const std::invalid_argument& e) {
      throw InputError(data.name + ": " + e.what());
    }
  }();
  const model::TrackerMethod m = method == "static"     ? model::TrackerMethod::kStatic
                                 : method == "interval" ? model::TrackerMethod::kInterval
                                                        : model::TrackerMethod::kQuasiDifferential;
  const model::GridSource source = model::TrackerLinesGridSource(data, tm, m, appendix_form);
  model::cli::GridCommand cmd =
      model::cli::ParseGridCommand(args, source.min_mm, source.max_mm, source.natural_spacing_mm);
  args.finish();

  std::map<std::string, std::string> info = source.info;
  info.emplace("builder", "volcomp build tracker");
  if (!cmd.json) std::cout << "volcomp build tracker\n";
  return model::cli::RunGridBuild(cmd, source.inverse, source.forward_or_null(), info, std::cout);
}

}  // namespace volcomp::tools
