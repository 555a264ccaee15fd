// The `volcomp-sim demo` command line.
#include "volcomp/sim/demo_cli.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "volcomp/sim/demo.hpp"
#include "volcomp/tools/args.hpp"

namespace volcomp::sim {

const char* DemoUsage() {
  return "  demo [--seed N] [--report DIR] [--model s500|CONFIG] [--points N] [--quick]\n"
         "       [--laser-noise-um S] [--tracker-noise-um S]\n"
         "       [--machine ideal|worn [--without SOURCE,...]]\n"
         "       the main job on the simulated machine: measure, evaluate, build the table,\n"
         "       upload it over the simulated CAN bus, reference, activate, re-measure;\n"
         "       worn: lost motion, scatter, screw error, thermal drift and a cross-axis sag,\n"
         "       compensated by 21-parameter GRID3, AXIS1D and a tracker-lattice GRID3\n"
         "       (SOURCE: lost-motion, scatter, screw, thermal, sag, misalignment)\n";
}

int RunDemoCommand(const std::vector<std::string>& words) {
  DemoOptions o;
  try {
    tools::Args args(words);
    if (auto s = args.integer("--seed")) {
      if (*s < 0) throw tools::UsageError("--seed must be >= 0");
      o.seed = static_cast<uint64_t>(*s);
    }
    if (auto d = args.value("--report")) o.report_dir = *d;
    if (auto m = args.value("--model")) o.model_spec = *m;
    const std::string machine = args.value("--machine").value_or("ideal");
    if (machine == "worn") {
      UseWornMachine(&o);
    } else if (machine != "ideal") {
      throw tools::UsageError("--machine must be ideal or worn");
    }
    if (auto w = args.value("--without")) {
      if (machine != "worn") throw tools::UsageError("--without needs --machine worn");
      size_t from = 0;
      while (from <= w->size()) {
        const size_t comma = std::min(w->find(',', from), w->size());
        const std::string name = w->substr(from, comma - from);
        if (!SwitchOff(name, &o)) {
          throw tools::UsageError("--without: unknown source \"" + name +
                                  "\" (lost-motion, scatter, screw, thermal, sag, misalignment)");
        }
        from = comma + 1;
      }
    }
    if (args.flag("--quick")) {  // a smaller run: fewer points and targets, same checks
      o.random_points = 50;
      o.diagonal_targets = 6;
      o.gost_targets = 6;
      o.benchmark_moves = 2;
      o.axis_run_pitch_mm = 40;
    }
    if (auto v = args.number("--laser-noise-um")) {
      if (!(*v >= 0)) throw tools::UsageError("--laser-noise-um must be >= 0");
      o.laser.linear_um.noise = *v;
    }
    if (auto v = args.number("--tracker-noise-um")) {
      if (!(*v >= 0)) throw tools::UsageError("--tracker-noise-um must be >= 0");
      o.tracker.coordinate_um.noise = *v;
    }
    if (auto n = args.integer("--points")) {
      if (*n < 1 || *n > 100000) throw tools::UsageError("--points must be 1..100000");
      o.random_points = static_cast<int>(*n);
    }
    args.finish();
  } catch (const tools::UsageError& e) {
    std::fprintf(stderr, "volcomp-sim demo: %s\n", e.what());
    return 2;
  }
  // The command-line boundary: a failed step and the builders' input errors end here.
  try {
    const SimResult<DemoResult> run = RunDemo(o, std::cout);
    if (!run.ok()) {
      std::fprintf(stderr, "volcomp-sim demo: %s\n", run.status().reason().c_str());
      return 1;
    }
    const DemoResult& r = run.value();
    PrintSummary(r, std::cout);
    if (!o.report_dir.empty()) {
      const SimStatus written = WriteDemoReport(r, o.report_dir);
      if (!written.ok()) {
        std::fprintf(stderr, "volcomp-sim demo: %s\n", written.reason().c_str());
        return 1;
      }
      std::cout << "report: " << o.report_dir << "/index.html (data, programs, measured model, "
                << "table.vct alongside)\n";
    }
    std::printf("wall time %.1f s\n", r.wall_s);
    return r.failures.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "volcomp-sim demo: %s\n", e.what());
    return 1;
  }
}

}  // namespace volcomp::sim
