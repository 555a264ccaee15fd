// GOST 27843 target plans, test cycles and G-code output.
#include "volcomp/metrology/test_program.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include "volcomp/metrology/inch.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::metrology {

namespace {

Unexpected<Failure> Impossible(std::string why) {
  return Fail(Error::kInvalidArgument, std::move(why));
}

}  // namespace

Expected<std::vector<double>> PlanGostTargets(const TargetPlan& plan) {
  if (plan.count < 2) return Impossible("at least 2 target positions are needed");
  if (!(plan.pitch > 0.0)) return Impossible("the pitch P must be positive");
  const double end = plan.rotary ? plan.start + 360.0 : plan.end;
  if (!(end > plan.start)) return Impossible("the end must be beyond the start");
  if (plan.fraction_digits < 1 || plan.fraction_digits > 4) {
    return Impossible("fraction digits must be 1..4");
  }
  const double travel = end - plan.start;
  // Whole pitches in the travel; (N + r)·P with N ≤ pitches − 1 and r < 1 stays inside it.
  const long pitches = static_cast<long>(std::floor(travel / plan.pitch + 1e-9));
  if (pitches < plan.count) {
    return Impossible("the travel holds only " + std::to_string(pitches) +
                      " pitches; fewer positions or a smaller pitch are needed");
  }
  std::mt19937 rng(plan.seed);
  const int scale = static_cast<int>(std::lround(std::pow(10.0, plan.fraction_digits)));
  std::uniform_int_distribution<int> fraction(0, scale - 1);
  std::set<int> used;
  std::vector<double> out;
  for (int j = 0; j < plan.count; ++j) {
    // Evenly spread integers N_j over the whole pitches.
    const double jd = static_cast<double>(j);
    const long n =
        plan.rotary ? static_cast<long>(std::floor(jd * static_cast<double>(pitches) / plan.count))
                    : std::lround(jd * static_cast<double>(pitches - 1) / (plan.count - 1));
    int f = 0;
    do {
      f = fraction(rng);
    } while (used.count(f) && used.size() < static_cast<std::size_t>(scale));
    used.insert(f);
    double p = plan.start + (static_cast<double>(n) + static_cast<double>(f) / scale) * plan.pitch;
    out.push_back(std::round(p * 1000.0) / 1000.0);
  }
  if (plan.rotary) {
    // §2.8: 0, 90, 180 and 270° are mandatory; each replaces the nearest planned target.
    for (double a : {0.0, 90.0, 180.0, 270.0}) {
      double t = plan.start + std::fmod(std::fmod(a - plan.start, 360.0) + 360.0, 360.0);
      std::size_t best = 0;
      for (std::size_t i = 1; i < out.size(); ++i) {
        if (std::fabs(out[i] - t) < std::fabs(out[best] - t)) best = i;
      }
      out[best] = t;
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Expected<std::vector<CycleMove>> BuildCycle(const std::vector<double>& targets,
                                            Cycle cycle,
                                            int runs,
                                            double overrun) {
  if (targets.size() < 2) return Impossible("at least 2 targets are needed");
  if (runs < 1) return Impossible("at least 1 run is needed");
  if (!(overrun > 0.0)) return Impossible("the overrun must be positive");
  std::vector<CycleMove> m;
  const int n = static_cast<int>(targets.size());
  auto stop = [&](int j, Direction d, int run) { m.push_back({targets[j - 1], true, d, run, j}); };
  auto pass = [&](double pos, Direction d, int run) { m.push_back({pos, false, d, run, 0}); };
  for (int run = 1; run <= runs; ++run) {
    pass(targets.front() - overrun, Direction::kDown, run);
    if (cycle == Cycle::kLinear) {
      for (int j = 1; j <= n; ++j) stop(j, Direction::kUp, run);
      pass(targets.back() + overrun, Direction::kUp, run);
      for (int j = n; j >= 1; --j) stop(j, Direction::kDown, run);
    } else {
      stop(1, Direction::kUp, run);
      for (int j = 2; j <= n; ++j) {
        stop(j, Direction::kUp, run);
        stop(j - 1, Direction::kDown, run);
      }
      pass(targets.back() + overrun, Direction::kUp, run);
      stop(n, Direction::kDown, run);
    }
  }
  pass(targets.front() - overrun, Direction::kDown, runs);
  return m;
}

Expected<std::string> EmitGcode(const std::vector<CycleMove>& moves, const GcodeOptions& o) {
  if (o.axes.empty() || o.axes.size() != o.origin.size() || o.axes.size() != o.direction.size()) {
    return Impossible("axes, origin and direction must have the same size");
  }
  const double unit = o.inch ? kMmPerInch : 1.0;  // mm per program unit
  const int decimals = o.inch ? o.decimals + 2 : o.decimals;
  std::ostringstream g;
  auto coords = [&](double pos) {
    std::string s;
    for (std::size_t a = 0; a < o.axes.size(); ++a) {
      s += (a ? " " : "") + o.axes[a] +
           report::FormatFixed((o.origin[a] + pos * o.direction[a]) / unit, decimals);
    }
    return s;
  };
  if (!o.title.empty()) {
    // An RS274NGC comment ends at the first ')' and may not contain '(' (LinuxCNC refuses the
    // program: "Nested comment found"), so the title's parentheses become brackets.
    std::string title = o.title;
    for (char& c : title) {
      if (c == '(') c = '[';
      if (c == ')') c = ']';
    }
    g << "(" << title << ")\n";
  }
  g << "(generated by volcomp; measured stops are marked with comments)\n";
  g << (o.inch ? "G20" : "G21") << " G90 G94\n";
  bool first = true;
  for (const auto& mv : moves) {
    if (first) {
      g << "G0 " << coords(mv.position) << "\n";
      g << "F" << report::FormatFixed(o.feed / unit, o.inch ? 3 : 0) << "\n";
      first = false;
      continue;
    }
    g << "G1 " << coords(mv.position);
    if (mv.measure) {
      g << " (P" << mv.target << " " << DirectionName(mv.approach) << " run " << mv.run << ")\n";
      g << "G4 P" << report::FormatFixed(o.dwell_s, 1) << "\n";
    } else {
      g << "\n";
    }
  }
  g << "M2\n";
  return g.str();
}

}  // namespace volcomp::metrology
