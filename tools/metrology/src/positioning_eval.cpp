// GOST 27843-88 / ISO 230-2:2014 positioning evaluation.
#include "volcomp/metrology/positioning_eval.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "volcomp/metrology/statistics.hpp"

namespace volcomp::metrology {
namespace {

Expected<DirectionStats> Stats(const ApproachSeries& s,
                               const EvaluationOptions& o,
                               double k,
                               const PositioningSet& set,
                               double target,
                               Direction dir) {
  DirectionStats st;
  st.n = static_cast<int>(s.size());
  st.mean = Mean(s.deviations);
  st.range = Range(s.deviations);
  if (o.sigma == SigmaMethod::kRange && o.standard == Standard::kGost27843) {
    const auto a = GostRangeCoefficient(st.n);
    if (!a) {
      std::ostringstream t;
      t.precision(10);
      t << target;
      return Fail(Error::kInputInvalid, set.source + ":" + std::to_string(s.lines.front()) +
                                            ": the range method (GOST 27843-88 formula (6)) "
                                            "needs 5 to 10 approaches; target " +
                                            t.str() + " " + DirectionSymbol(dir) + " has " +
                                            std::to_string(st.n));
    }
    st.s = st.range * *a;
  } else {
    st.s = SampleStdDev(s.deviations);
  }
  st.upper = st.mean + k * st.s;
  st.lower = st.mean - k * st.s;
  st.repeatability = 2.0 * k * st.s;
  return st;
}

// Value of one direction at a position, or nullopt.
using Getter = std::function<std::optional<double>(const PositionStats&, Direction)>;

// Max and min of `get` over the positions and the given directions.
std::optional<Span> SpanOf(const std::vector<PositionStats>& ps,
                           const Getter& get_max,
                           const Getter& get_min,
                           bool up,
                           bool down) {
  std::optional<Span> out;
  bool have_max = false, have_min = false;
  Span s;
  for (const auto& p : ps) {
    for (int d = 0; d < 2; ++d) {
      if ((d == 0 && !up) || (d == 1 && !down)) continue;
      const Direction dir = d == 0 ? Direction::kUp : Direction::kDown;
      if (const auto v = get_max(p, dir); v && (!have_max || *v > s.max.value)) {
        s.max = {*v, p.index, dir};
        have_max = true;
      }
      if (const auto v = get_min(p, dir); v && (!have_min || *v < s.min.value)) {
        s.min = {*v, p.index, dir};
        have_min = true;
      }
    }
  }
  if (have_max && have_min) {
    s.value = s.max.value - s.min.value;
    out = s;
  }
  return out;
}

const std::optional<DirectionStats>& Dir(const PositionStats& p, Direction d) {
  return d == Direction::kUp ? p.up : p.down;
}

}  // namespace

const char* StandardName(Standard s) {
  return s == Standard::kGost27843 ? "GOST 27843-88" : "ISO 230-2:2014";
}

double CoverageFactor(Standard s) { return s == Standard::kGost27843 ? 3.0 : 2.0; }

Expected<PositioningResult> EvaluatePositioning(const PositioningSet& set,
                                                const EvaluationOptions& options) {
  PositioningResult r;
  r.standard = options.standard;
  r.sigma = options.standard == Standard::kGost27843 ? options.sigma : SigmaMethod::kFormula;
  r.k = CoverageFactor(options.standard);
  r.kind = set.kind;
  r.bidirectional = set.has_up && set.has_down;
  r.warnings = set.warnings;
  EvaluationOptions o = options;
  o.sigma = r.sigma;

  for (std::size_t i = 0; i < set.positions.size(); ++i) {
    const TargetPosition& tp = set.positions[i];
    PositionStats ps;
    ps.index = i;
    ps.target = tp.target;
    if (!tp.up.empty()) {
      VOLCOMP_TRY_ASSIGN(ps.up, Stats(tp.up, o, r.k, set, tp.target, Direction::kUp));
    }
    if (!tp.down.empty()) {
      VOLCOMP_TRY_ASSIGN(ps.down, Stats(tp.down, o, r.k, set, tp.target, Direction::kDown));
    }
    if (ps.up && ps.down) {
      ps.reversal = ps.up->mean - ps.down->mean;
      ps.mean_bidirectional = 0.5 * (ps.up->mean + ps.down->mean);
      ps.repeatability_bidirectional =
          std::max({r.k * ps.up->s + r.k * ps.down->s + std::fabs(*ps.reversal),
                    ps.up->repeatability, ps.down->repeatability});
    }
    r.positions.push_back(ps);
  }
  const auto& P = r.positions;

  const Getter upper = [](const PositionStats& p, Direction d) -> std::optional<double> {
    const auto& s = Dir(p, d);
    return s ? std::optional<double>(s->upper) : std::nullopt;
  };
  const Getter lower = [](const PositionStats& p, Direction d) -> std::optional<double> {
    const auto& s = Dir(p, d);
    return s ? std::optional<double>(s->lower) : std::nullopt;
  };
  const Getter mean = [](const PositionStats& p, Direction d) -> std::optional<double> {
    const auto& s = Dir(p, d);
    return s ? std::optional<double>(s->mean) : std::nullopt;
  };
  const Getter bimean = [](const PositionStats& p, Direction d) -> std::optional<double> {
    return d == Direction::kUp ? p.mean_bidirectional : std::nullopt;
  };

  if (set.has_up) {
    r.accuracy_up = SpanOf(P, upper, lower, true, false);
    r.systematic_up = SpanOf(P, mean, mean, true, false);
  }
  if (set.has_down) {
    r.accuracy_down = SpanOf(P, upper, lower, false, true);
    r.systematic_down = SpanOf(P, mean, mean, false, true);
  }
  for (int d = 0; d < 2; ++d) {
    const Direction dir = d == 0 ? Direction::kUp : Direction::kDown;
    std::optional<Extreme> best;
    for (const auto& p : P) {
      const auto& s = Dir(p, dir);
      if (s && (!best || s->repeatability > best->value))
        best = Extreme{s->repeatability, p.index, dir};
    }
    (d == 0 ? r.repeatability_up : r.repeatability_down) = best;
  }
  if (r.bidirectional) {
    r.accuracy = SpanOf(P, upper, lower, true, true);
    r.systematic = SpanOf(P, mean, mean, true, true);
    r.mean_bidirectional_range = SpanOf(P, bimean, bimean, true, false);
    if (r.mean_bidirectional_range) {
      r.mean_bidirectional_range->max.direction.reset();
      r.mean_bidirectional_range->min.direction.reset();
    }
    double sum_b = 0.0, sum_r = 0.0;
    for (const auto& p : P) {
      if (!r.repeatability || *p.repeatability_bidirectional > r.repeatability->value) {
        r.repeatability = Extreme{*p.repeatability_bidirectional, p.index, std::nullopt};
      }
      if (!r.reversal_max || std::fabs(*p.reversal) > r.reversal_max->value) {
        r.reversal_max = Extreme{std::fabs(*p.reversal), p.index, std::nullopt};
      }
      sum_b += *p.reversal;
      sum_r += p.up->repeatability + p.down->repeatability;
    }
    const double m = static_cast<double>(P.size());
    r.reversal_mean = sum_b / m;
    r.mean_repeatability = sum_r / (2.0 * m);
  }
  return r;
}

}  // namespace volcomp::metrology
