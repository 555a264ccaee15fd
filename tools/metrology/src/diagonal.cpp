// ISO 230-6 diagonal plans and evaluation.
#include "volcomp/metrology/diagonal.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/reading_checks.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::metrology {
namespace {

std::string Num(double v) { return report::FormatNumber(v); }

// Minimum target count of §5.2: 5 per metre of diagonal, and 5 in total.
std::size_t RequiredTargets(double length_mm) {
  return std::max<std::size_t>(
      5, static_cast<std::size_t>(std::ceil(5.0 * length_mm / 1000.0 - 1e-9)));
}

// Body diagonals are the same line when their corner signs agree up to a common sign.
std::array<int, 3> Canonical(const std::array<int, 3>& s) {
  const int first = s[0] != 0 ? s[0] : (s[1] != 0 ? s[1] : s[2]);
  return {s[0] * first, s[1] * first, s[2] * first};
}

}  // namespace

Expected<DiagonalPlan> PlanDiagonal(const Vec3& p1, const Vec3& p2, double increment_mm) {
  if (!(increment_mm > 0.0) || !std::isfinite(increment_mm)) {
    return Fail(Error::kInvalidArgument, "the diagonal increment must be positive");
  }
  DiagonalPlan p;
  p.p1 = p1;
  p.p2 = p2;
  p.travel_mm = {p2.x - p1.x, p2.y - p1.y, p2.z - p1.z};
  p.length_mm = std::sqrt(p.travel_mm.x * p.travel_mm.x + p.travel_mm.y * p.travel_mm.y +
                          p.travel_mm.z * p.travel_mm.z);
  if (!(p.length_mm > 0.0)) return Fail(Error::kInvalidArgument, "P1 and P2 are the same point");
  p.steps = std::max(1, static_cast<int>(std::lround(p.length_mm / increment_mm)));
  p.increment_mm = p.length_mm / p.steps;
  const double f = p.increment_mm / p.length_mm;
  p.axis_increment_mm = {f * p.travel_mm.x, f * p.travel_mm.y, f * p.travel_mm.z};
  for (int i = 0; i <= p.steps; ++i) {
    const double t = static_cast<double>(i) / p.steps;
    p.distances.push_back(t * p.length_mm);
    p.points.push_back(
        {p1.x + t * p.travel_mm.x, p1.y + t * p.travel_mm.y, p1.z + t * p.travel_mm.z});
  }
  if (std::fabs(p.increment_mm - increment_mm) > 1e-9 * increment_mm) {
    p.warnings.push_back("increment adjusted from " + Num(increment_mm) + " to " +
                         Num(p.increment_mm) + " mm so that " + std::to_string(p.steps) +
                         " steps span the diagonal of " + Num(p.length_mm) + " mm");
  }
  const std::size_t need = RequiredTargets(p.length_mm);
  if (p.distances.size() < need) {
    p.warnings.push_back("ISO 230-6 §5.2: " + std::to_string(p.distances.size()) + " targets on " +
                         Num(p.length_mm) + " mm; at least 5 per metre and 5 " + "in total give " +
                         std::to_string(need));
  }
  return p;
}

Expected<DiagonalEvaluation> EvaluateDiagonals(const tools::CsvTable& table,
                                               const GroupingOptions& options,
                                               const PositioningUncertaintyInputs& uncertainty) {
  VOLCOMP_TRY_ASSIGN(const std::size_t diag_col, table.Require("diagonal"));
  if (table.first_of({"target_deg"})) {
    return Fail(table.LineFailure(table.header_line(),
                                  "diagonal tests are linear: use target_mm, not target_deg"));
  }
  VOLCOMP_TRY_ASSIGN(const PositioningData all, ReadPositioningCsv(table));
  if (all.readings.size() != table.rows().size()) {
    return Fail(table.LineFailure(table.header_line(), "diagonal data must use the long layout"));
  }
  DiagonalEvaluation ev;
  ev.source = table.source();
  ev.conditions = ConditionsFromPreamble(table);
  VOLCOMP_TRY_ASSIGN(const PositioningUncertaintyInputs u_inputs,
                     CompleteFromPreamble(uncertainty, ev.conditions));
  std::vector<std::string> u_warnings;  // the same for every diagonal: listed once
  std::vector<std::string> order;
  std::map<std::string, PositioningData> per;
  std::map<std::string, DiagonalName> names;
  for (std::size_t i = 0; i < table.rows().size(); ++i) {
    const auto& row = table.rows()[i];
    const std::string& text = row.fields()[diag_col];  // rows have the header's fields
    const auto name = ParseDiagonalName(text);
    if (!name) {
      return Fail(table.LineFailure(row.line(), "column \"diagonal\": \"" + text +
                                                    "\" is not a diagonal name (e.g. +X+Y-Z, "
                                                    "PPN, +X-Y, +X-Y Z300, NP)"));
    }
    auto it = per.find(name->text);
    if (it == per.end()) {
      order.push_back(name->text);
      names[name->text] = *name;
      PositioningData d;
      d.source = all.source;
      d.column = all.column;
      d.column_scale = all.column_scale;
      it = per.emplace(name->text, d).first;
    }
    it->second.readings.push_back(all.readings[i]);
  }

  EvaluationOptions eo;
  eo.standard = Standard::kIso230_2;
  std::map<std::string, DiagonalGroupValue> groups;
  std::vector<std::string> group_order;
  std::set<std::array<int, 3>> body_lines;
  for (const std::string& key : order) {
    const PositioningData& data = per[key];
    VOLCOMP_TRY_ASSIGN(const PositioningSet set, GroupReadings(data, options));
    if (!(set.has_up && set.has_down)) {
      return Fail(Error::kInputInvalid,
                  data.source + ":" + std::to_string(data.readings.front().line) + ": diagonal " +
                      key +
                      " has only one direction; ISO 230-6 §5.3 needs 5 approaches in each "
                      "direction");
    }
    DiagonalResult d;
    d.name = names[key];
    VOLCOMP_TRY_ASSIGN(d.evaluation, EvaluatePositioning(set, eo));
    d.length_mm = set.positions.back().target - set.positions.front().target;
    VOLCOMP_TRY_ASSIGN(d.evaluation.uncertainty,
                       LengthUncertainty(u_inputs, d.length_mm, &u_warnings));
    d.E = *d.evaluation.systematic;
    d.B = *d.evaluation.reversal_max;
    for (const auto& w : set.warnings) ev.warnings.push_back("diagonal " + key + ": " + w);
    ReadingCheckOptions check;
    check.travel = d.length_mm;
    for (const auto& w : CheckReadings(data, set, check)) {
      ev.warnings.push_back("diagonal " + key + ": " + w);
    }
    const std::size_t need = RequiredTargets(d.length_mm);
    if (set.positions.size() < need) {
      ev.warnings.push_back("diagonal " + key +
                            ": ISO 230-6 §5.2: " + std::to_string(set.positions.size()) +
                            " targets on " + Num(d.length_mm) + " mm; at least " +
                            std::to_string(need) + " (5 per metre, 5 in total)");
    }
    std::string gkey = "body";
    if (!d.name.body) gkey = d.name.plane + (d.name.offset.empty() ? "" : " " + d.name.offset);
    if (d.name.body && !body_lines.insert(Canonical(d.name.signs)).second) {
      ev.warnings.push_back("diagonal " + key +
                            " is the same body diagonal as another one in "
                            "the file, measured from the other end");
    }
    auto g = groups.find(gkey);
    if (g == groups.end()) {
      group_order.push_back(gkey);
      g = groups
              .emplace(gkey, DiagonalGroupValue{gkey, -1.0, key, -1.0, key, 0, std::nullopt,
                                                std::nullopt})
              .first;
    }
    DiagonalGroupValue& gv = g->second;
    std::optional<double> u_length, u_local;
    if (d.evaluation.uncertainty) {
      u_length = d.evaluation.uncertainty->span_u;
      u_local = d.evaluation.uncertainty->local_u;
    }
    if (d.E.value > gv.E_d) gv.E_d = d.E.value, gv.E_from = key, gv.E_d_U = u_length;
    if (d.B.value > gv.B_d) gv.B_d = d.B.value, gv.B_from = key, gv.B_d_U = u_local;
    ++gv.diagonals;
    ev.diagonals.push_back(std::move(d));
  }
  for (const auto& w : u_warnings) {
    if (std::find(ev.warnings.begin(), ev.warnings.end(), w) == ev.warnings.end()) {
      ev.warnings.push_back(w);
    }
  }
  for (const auto& key : group_order) {
    if (key == "body") {
      ev.body = groups[key];
      if (body_lines.size() < 4) {
        ev.warnings.push_back("only " + std::to_string(body_lines.size()) +
                              " of the 4 body diagonals measured: E_d and B_d (ISO 230-6 §3.4, "
                              "§3.6) cover those only");
      }
    } else {
      ev.faces.push_back(groups[key]);
      if (groups[key].diagonals < 2) {
        ev.warnings.push_back("face " + key +
                              ": one diagonal only; E_d(ab) and B_d(ab) "
                              "(§3.5, §3.7) are the maximum of the two diagonals of the plane");
      }
    }
  }
  return ev;
}

std::string DiagonalReportName(const DiagonalEvaluation& ev) {
  std::vector<std::string> tokens;
  for (const auto& d : ev.diagonals) tokens.push_back(DiagonalFileToken(d.name));
  std::sort(tokens.begin(), tokens.end());
  std::string name = "diagonal";
  for (const auto& t : tokens) name += "_" + t;
  return name;
}

}  // namespace volcomp::metrology
