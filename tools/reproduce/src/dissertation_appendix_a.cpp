// Dissertation Appendix А (seed 001 lines 2996-3089): the Mathcad worksheet of chapter 3's
// algorithm at node n_x/n_y/n_z = 15/15/5 (300/150/50 mm), k = 1, r = (10, 10, 10) mm, with its
// intermediate values: the 18 inputs, the angles in degrees/minutes/seconds, A, B, C, the
// Rodrigues coefficient l, δp, δo, δ and the signed % differences. Computed by tools/model
// DissertationError on the node's rows of Tables 3.2-3.4 (tools/datasets).
#include <cmath>
#include <string>
#include <utility>

#include "dissertation_tables.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/dissertation.hpp"
#include "volcomp/tools/math_constants.hpp"

namespace volcomp::reproduce::dissertation {
namespace {

using model::DissertationCase;
using model::DissertationError;
using model::DissertationOptions;
using model::DissertationResult;
using model::PointErrors;

using tools::kPi;

// The inputs as the appendix prints them (line 3009: ρ, line 3011: ε), [axis][direction].
const char* const kPrintedRho[3][3] = {{"30.566667", "4.733333", "0.3"},
                                       {"-7.45", "47.6", "0.1"},
                                       {"0.333333", "14.583333", "-5.633333"}};
const char* const kPrintedEps[3][3] = {{"0.03526", "0.03196", "0.05105"},
                                       {"-0.02663", "0.01108", "0.02126"},
                                       {"0.00188", "0.01007", "-0.00493"}};
const char* const kAxisLetter = "xyz";

// Lines 3013-3014: each angle as atan(ε/1000) in degrees, minutes and seconds (printed order).
struct AngleRow {
  int axis, direction;
  const char* deg;
  const char* min;
  const char* sec;
};
const AngleRow kAngles[9] = {
    {0, 0, "0.002", "0.121", "7.273"},    {1, 0, "-0.002", "-0.092", "-5.493"},
    {0, 1, "0.002", "0.11", "6.592"},     {1, 1, "6.348e-4", "0.038", "2.285"},
    {0, 2, "0.003", "0.175", "10.53"},    {1, 2, "0.001", "0.073", "4.385"},
    {2, 0, "1.077e-4", "0.006", "0.388"}, {2, 2, "-2.825e-4", "-0.017", "-1.017"},
    {2, 1, "5.77e-4", "0.035", "2.077"},
};

std::string Name(char kind, int axis, int direction) {
  return std::string(kind == 'r' ? "ρ_" : "ε_") + kAxisLetter[axis] + kAxisLetter[direction];
}

}  // namespace

Expected<void> AddAppendixA(SeedReproduction& out) {
  VOLCOMP_TRY_ASSIGN(const PointErrors p, datasets::S500PointErrorsAtNode(15, 15, 5));
  DissertationOptions o;
  o.which = DissertationCase::kPlus;
  const DissertationResult plus = DissertationError(p, o);
  o.which = DissertationCase::kMinus;
  const DissertationResult minus = DissertationError(p, o);
  o.which = DissertationCase::kFirstOrder;
  const DissertationResult first = DissertationError(p, o);

  Table table;
  table.seed = kSeed;
  table.id = "А";
  table.title =
      "Appendix А: the chapter 3 algorithm (Mathcad) at node 15/15/5 (300/150/50 mm), k = 1";
  table.source = SourceLine(2996,
                            "Appendix А; inputs 3009-3011, angles 3013-3014, results "
                            "3018-3042");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      table.cells.push_back(
          MakeCell(Name('r', i, j), "input", "µm", kPrintedRho[i][j], p.delta_um[i][j]));
      table.cells.push_back(
          MakeCell(Name('e', i, j), "input", "µm/mm", kPrintedEps[i][j], p.eps_um_per_mm[i][j]));
    }
  for (const AngleRow& a : kAngles) {
    const double deg = std::atan(p.eps_um_per_mm[a.axis][a.direction] / 1000.0) * 180.0 / kPi;
    const std::string row = Name('e', a.axis, a.direction);
    table.cells.push_back(MakeCell(row, "atan(ε/1000), degrees", "°", a.deg, deg));
    table.cells.push_back(MakeCell(row, "in arc-minutes", "'", a.min, deg * 60.0));
    table.cells.push_back(MakeCell(row, "in arc-seconds", "\"", a.sec, deg * 3600.0));
  }
  const auto add = [&table](const char* row, const char* column, const char* unit,
                            const char* printed, double computed) {
    table.cells.push_back(MakeCell(row, column, unit, printed, computed));
  };
  add("p (all ± = +)", "A", "rad", "0.000010512", plus.a_rad);
  add("o (all ± = −)", "A", "rad", "0.000010508", minus.a_rad);
  add("p (all ± = +)", "B", "rad", "0.000053111", plus.b_rad);
  add("o (all ± = −)", "B", "rad", "0.000053109", minus.b_rad);
  add("p (all ± = +)", "C", "rad", "0.00006738", plus.c_rad);
  add("o (all ± = −)", "C", "rad", "0.00006738", minus.c_rad);
  add("p (all ± = +)", "l", "", "0.999999998", plus.l);
  add("o (all ± = −)", "l", "", "0.999999998", minus.l);
  add("p (all ± = +)", "δp", "µm", "54.789011", plus.norm_um);
  add("o (all ± = −)", "δo", "µm", "54.789025", minus.norm_um);
  add("first order", "A", "rad", "1.051e-5", first.a_rad);
  add("first order", "B", "rad", "5.311e-5", first.b_rad);
  add("first order", "C", "rad", "6.738e-5", first.c_rad);
  add("first order", "δ", "µm", "54.789039", first.norm_um);
  add("p (all ± = +)", "((δp/δ) − 1)·100", "%", "-5.08e-5",
      (plus.norm_um / first.norm_um - 1.0) * 100.0);
  add("o (all ± = −)", "((δo/δ) − 1)·100", "%", "-2.417e-5",
      (minus.norm_um / first.norm_um - 1.0) * 100.0);
  table.notes.push_back(
      "The inputs are rows 15, 15, 5 of Tables 3.2-3.4 as compiled into tools/datasets; "
      "the appendix prints the same numbers.");
  table.notes.push_back(
      "The worksheet prints A_p as 10^-3·(ε_xx + ε_yy + ε_zz): a misprint, its value 0.000010512 "
      "is that of ε_xx + ε_yx + ε_zx (digest D4.3); its second-order term printed ε_yz·ε_zx is "
      "ε_yz·ε_zy in the values (D4.4). Formulas, not numbers: nothing to flag in a cell.");
  table.notes.push_back(
      "C is printed with 8 decimals (0.00006738, the trailing 0 of 9 dropped): tolerance 5·10^-9.");
  out.tables.push_back(std::move(table));
  return {};
}

}  // namespace volcomp::reproduce::dissertation
