// `volcomp build tracker`: a GRID3 image from laser-tracker axis lines by the dissertation's
// tangential methods (ch. 2): static, interval or quasi-differential, with printed (sign-dropped),
// signed or scaled direction vectors. See docs/table-builders.md.
#include <array>
#include <iostream>
#include <map>
#include <string>

#include "commands.hpp"
#include "volcomp/model/build_cli.hpp"
#include "volcomp/model/io.hpp"
#include "volcomp/model/tracker.hpp"

namespace volcomp::tools {

int RunBuildTracker(Args& args) {
  const auto points = args.value("--points");
  const auto builtin = args.value("--builtin");
  if (points.has_value() == builtin.has_value()) {
    throw UsageError("give either --points FILE or --builtin s500-315|s500-240");
  }
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
  std::array<double, 3> lo = {0, 0, 0}, hi, natural;
  for (int a = 0; a < 3; ++a) {
    const auto& line = data.lines[static_cast<std::size_t>(a)];
    hi[static_cast<std::size_t>(a)] = line.back().q_mm;
    natural[static_cast<std::size_t>(a)] = tm.step_mm(a);
  }
  model::cli::GridCommand cmd = model::cli::ParseGridCommand(args, lo, hi, natural);
  args.finish();

  model::InverseMap inverse;
  model::ForwardMap forward;
  bool check = false;
  if (method == "static") {
    inverse = [&tm](const model::Vec3& t) { return tm.Static(t).command_mm; };
    forward = [&tm](const model::Vec3& q) { return tm.StaticPosition_mm(q); };
    check = true;
  } else if (method == "interval") {
    inverse = [&tm](const model::Vec3& t) { return tm.Interval(t).command_mm; };
  } else if (appendix_form) {
    inverse = [&tm](const model::Vec3& t) { return tm.QuasiDifferential(t).command_mm; };
  } else {
    inverse = [&tm](const model::Vec3& t) { return tm.ExactInverse(t).command_mm; };
    forward = [&tm](const model::Vec3& q) { return tm.Position_mm(q); };
    check = true;
  }
  const std::map<std::string, std::string> info = {
      {"builder", "volcomp build tracker"},
      {"data", data.name},
      {"method", method + (method == "quasi-differential"
                               ? (appendix_form ? " (Appendix Г form)" : " (exact inverse)")
                               : "")},
      {"cosines", cosines},
      {"origin", origin},
  };
  if (!cmd.json) std::cout << "volcomp build tracker\n";
  return model::cli::RunGridBuild(cmd, inverse, check ? &forward : nullptr, info, std::cout);
}

}  // namespace volcomp::tools
