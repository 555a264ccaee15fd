// `volcomp-sim demo`: the main job on the simulated machine (docs/simulator.md).
#include <algorithm>
#include <cstdio>

#include "commands.hpp"
#include "volcomp/sim/demo.hpp"

namespace volcomp::sim {
namespace {

// `--without a,b,...`: every named source off, or a usage failure naming the unknown one.
Outcome SwitchOffSources(const std::string& list, DemoOptions* o) {
  size_t from = 0;
  while (from <= list.size()) {
    const size_t comma = std::min(list.find(',', from), list.size());
    const std::string name = list.substr(from, comma - from);
    if (!SwitchOff(name, o)) {
      return UsageFailure("--without: unknown source \"" + name +
                          "\" (lost-motion, scatter, screw, thermal, sag, misalignment)");
    }
    from = comma + 1;
  }
  return Outcome::Ok();
}

Expected<int> RunDemoCommand(args::Args& args, Context& ctx) {
  const auto seed = args.Integer("--seed");
  const auto report = args.Value("--report");
  const auto model = args.Value("--model");
  const std::string machine = args.Value("--machine").value_or("ideal");
  const auto without = args.Value("--without");
  const bool quick = args.Flag("--quick");
  const auto laser_noise = args.Number("--laser-noise-um");
  const auto tracker_noise = args.Number("--tracker-noise-um");
  const auto points = args.Integer("--points");
  VOLCOMP_TRY(args.Finish());

  DemoOptions o;
  if (seed) {
    if (*seed < 0) return UsageFailure("--seed must be >= 0");
    o.seed = static_cast<uint64_t>(*seed);
  }
  if (report) o.report_dir = *report;
  if (model) o.model_spec = *model;
  if (machine == "worn") {
    UseWornMachine(&o);
  } else if (machine != "ideal") {
    return UsageFailure("--machine must be ideal or worn");
  }
  if (without) {
    if (machine != "worn") return UsageFailure("--without needs --machine worn");
    VOLCOMP_TRY(SwitchOffSources(*without, &o));
  }
  if (quick) {  // a smaller run: fewer points and targets, same checks
    o.random_points = 50;
    o.diagonal_targets = 6;
    o.gost_targets = 6;
    o.benchmark_moves = 2;
    o.axis_run_pitch_mm = 40;
  }
  if (laser_noise) {
    if (!(*laser_noise >= 0)) return UsageFailure("--laser-noise-um must be >= 0");
    o.laser.linear_um.noise = *laser_noise;
  }
  if (tracker_noise) {
    if (!(*tracker_noise >= 0)) return UsageFailure("--tracker-noise-um must be >= 0");
    o.tracker.coordinate_um.noise = *tracker_noise;
  }
  if (points) {
    if (*points < 1 || *points > 100000) return UsageFailure("--points must be 1..100000");
    o.random_points = static_cast<int>(*points);
  }

  VOLCOMP_TRY_ASSIGN(const DemoResult r, RunDemo(o, ctx.out));
  PrintSummary(r, ctx.out);
  if (!o.report_dir.empty()) {
    VOLCOMP_TRY(WriteDemoReport(r, o.report_dir));
    ctx.out << "report: " << o.report_dir << "/index.html (data, programs, measured model, "
            << "table.vct alongside)\n";
  }
  char wall[64];
  std::snprintf(wall, sizeof wall, "wall time %.1f s\n", r.wall_s);
  ctx.out << wall;
  return r.failures.empty() ? 0 : 1;
}

}  // namespace

const Command& DemoCommand() {
  static const Command command{
      "demo",
      "  demo [--seed N] [--report DIR] [--model s500|CONFIG] [--points N] [--quick]\n"
      "       [--laser-noise-um S] [--tracker-noise-um S]\n"
      "       [--machine ideal|worn [--without SOURCE,...]]\n"
      "       the main job on the simulated machine: measure, evaluate, build the table,\n"
      "       upload it over the simulated CAN bus, reference, activate, re-measure;\n"
      "       worn: lost motion, scatter, screw error, thermal drift and a cross-axis sag,\n"
      "       compensated by 21-parameter GRID3, AXIS1D and a tracker-lattice GRID3\n"
      "       (SOURCE: lost-motion, scatter, screw, thermal, sag, misalignment)\n",
      RunDemoCommand};
  return command;
}

}  // namespace volcomp::sim
