// Dissertation Appendices Б, В, Г (seed 001 lines 3090-3237): the Mathcad sheets of the static,
// interval and quasi-differential tracker methods at the target (130, 140, 106) on the 315 mm
// cube data, with their intermediate values. Computed by tools/model TrackerModel with the
// printed (unsigned) cosines, which is what the author's software used (ch. 1-2 digest E1), on
// the Tables 2.10-2.12 compiled into tools/datasets.
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "dissertation_tables.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/tracker.hpp"

namespace volcomp::reproduce::dissertation {
namespace {

using model::Mat3;
using model::TrackerModel;
using model::Vec3;

const char* const kAxis[3] = {"x", "y", "z"};
const Vec3 kTarget = {130, 140, 106};

void AddMatrix(Table& t, const char* const (&p)[9], const Mat3& g, const char* misprint22 = "") {
  for (int i = 0; i < 9; ++i) {
    Cell c = MakeCell("G", "G[" + std::to_string(i / 3) + "][" + std::to_string(i % 3) + "]", "",
                      p[i], g.m[static_cast<std::size_t>(i)], i == 8 ? misprint22 : "");
    c.tolerance = 1e-7;
    t.cells.push_back(std::move(c));
  }
}

/// The target's cell n = trunc(r/u), printed 8, 9, 7 by both sheets.
void AddCell(Table& t, const std::array<int, 3>& n) {
  const char* const kPrinted[3] = {"8", "9", "7"};
  for (int i = 0; i < 3; ++i)
    t.cells.push_back(MakeCell("cell", std::string("n_") + kAxis[i], "", kPrinted[i],
                               n[static_cast<std::size_t>(i)]));
}

/// The two X-line nodes read into A (rows of Table 2.10; the sheet shows the workbook's 9
/// decimals).
void AddNodes(Table& t, const model::TrackerData& data, int first, const char* const (&p)[6]) {
  for (int k = 0; k < 2; ++k) {
    const model::TrackerNode& n = data.lines[0][static_cast<std::size_t>(first + k)];
    const std::string row = "A, X node " + std::to_string(static_cast<int>(n.q_mm)) + " mm";
    for (int i = 0; i < 3; ++i) {
      Cell c =
          MakeCell(row, std::string(kAxis[i]) + "_tr", "mm", p[3 * k + i], Component(n.p_mm, i));
      c.tolerance = 5e-8;  // the table prints 7 decimals
      t.cells.push_back(std::move(c));
    }
  }
}

const char* const kInputsNote =
    "A (two X-line nodes) is printed with the workbook's 9 decimals, Table 2.10 with 7: compared "
    "to ±5·10^-8 mm. G is compared to ±1·10^-7 (unit vectors of 7-decimal readings, ch. 1-2 "
    "digest §3.8), r01 to ±5·10^-8 mm (digest §1.6: within 4 nm); the rest to half a unit of "
    "the last printed digit.";

}  // namespace

Expected<void> AddAppendicesBVG(SeedReproduction& out) {
  const model::TrackerData data = datasets::S500Tracker315();
  model::TrackerOptions o;
  o.cosines = model::CosineSource::kPrinted;
  VOLCOMP_TRY_ASSIGN(const TrackerModel m, TrackerModel::Create(data, o));
  VOLCOMP_TRY_ASSIGN(const model::TrackerStaticResult s, m.Static(kTarget));
  VOLCOMP_TRY_ASSIGN(const model::TrackerIntervalResult iv, m.Interval(kTarget));
  VOLCOMP_TRY_ASSIGN(const model::TrackerQuasiResult qd, m.QuasiDifferential(kTarget));

  const char* const kNodes15[6] = {"14.993629404", "0.005684907", "0.006235739",
                                   "29.991876303", "0.013872846", "0.006475148"};
  const char* const kR01Static[3] = {"-0.006368359", "-0.002503989", "0.005996301"};
  const char* const kGStatic[9] = {"0.999999851", "0.000371486", "0.000497191",
                                   "0.000545926", "0.999999883", "0.00002308",
                                   "0.000015963", "0.000309413", "0.999999876"};
  const char* const kGCell[9] = {"0.999999894", "0.000961343", "0.000693666",
                                 "0.000433208", "0.999999496", "0.000136283",
                                 "0.00015392",  "0.000289538", "0.99999975"};
  {
    Table t = NewTable("Б", "Appendix Б: tangential static method at (130, 140, 106), 315 mm cube",
                       SourceLine(3090, "Appendix Б; A 3100, r01 3114, G 3126, q 3128"));
    AddNodes(t, data, 1, kNodes15);
    AddVector(t, "r01", "r01", "mm", kR01Static, s.r01_mm, "", 5e-8);
    AddMatrix(t, kGStatic, s.g);
    AddVector(t, "q (command)", "q", "mm", {"129.902", "139.929", "105.949"}, s.command_mm);
    t.notes = {kInputsNote,
               "Inputs: q1T = 15 mm and the interval 15-30 mm of every axis (as the sheet "
               "chooses them), the printed unsigned cosines of Tables 2.10-2.12."};
    out.tables.push_back(std::move(t));
  }
  {
    Table t = NewTable("В", "Appendix В: tangential interval method at (130, 140, 106)",
                       SourceLine(3130, "Appendix В; n 3140, A 3148, r01 3162, G 3174, q 3176"));
    AddCell(t, iv.n);
    AddNodes(t, data, 8,
             {"120.024503377", "0.060629453", "0.030831463", "135.044047267", "0.067136045",
              "0.033143278"});
    AddVector(t, "r01", "r01", "mm", {"0.024516059", "0.008644461", "0.012361005"}, iv.r01_mm, "",
              1e-6);
    // As Appendix В prints it: Г's matrix but for G22.
    const char* const kGInterval[9] = {"0.999999894", "0.000961343", "0.000693666",
                                       "0.000433208", "0.999999496", "0.000136283",
                                       "0.00015392",  "0.000289538", "0.999999975"};
    AddMatrix(t, kGInterval, iv.g,
              "stray 9: 0.99999975 (Appendix Г; sqrt(1 − 0.000693666² − 0.000136283²) = "
              "0.9999997501, digest E2)");
    AddVector(t, "q (command)", "q", "mm", {"129.768", "139.921", "105.927"}, iv.command_mm);
    t.notes = {kInputsNote,
               "r01 is back-extrapolated from the nodes 120 and 135 mm to 0 (q1T = 120): the "
               "7-decimal rounding of the readings grows eightfold, so r01 is compared to "
               "±1·10^-6 mm."};
    out.tables.push_back(std::move(t));
  }
  {
    Table t =
        NewTable("Г", "Appendix Г: tangential quasi-differential method at (130, 140, 106)",
                 SourceLine(3178, "Appendix Г; n 3184, A 3196, r01 3210, ΔR 3228, γ 3234, q 3236"));
    AddCell(t, qd.n);
    AddNodes(t, data, 1, kNodes15);
    AddVector(t, "r01", "r01", "mm", kR01Static, m.origin_mm(), "", 5e-8);
    AddVector(t, "R", "R", "mm", {"120.150625141", "135.105955968", "105.106431456"}, qd.r_mm, "",
              5e-6);
    const Vec3 r0 = RoundedToMicrometre(qd.r_mm);
    AddVector(t, "R0 (R rounded)", "R0", "mm", {"120.151", "135.106", "105.106"}, r0);
    AddVector(t, "ΔR = r − R0", "ΔR", "mm", {"9.849", "4.894", "0.894"}, kTarget - r0);
    AddMatrix(t, kGCell, qd.g);
    AddVector(t, "γ = G⁻¹·ΔR", "γ", "mm", {"9.844", "4.89", "0.891"}, qd.gamma_mm);
    AddVector(t, "q (command)", "q", "mm", {"129.844", "139.89", "105.891"}, qd.command_mm);
    t.notes = {kInputsNote,
               "R is compared to ±5·10^-6 mm: the sheet sums 8 + 9 + 7 intervals of unit vectors "
               "the workbook holds with more digits than Tables 2.10-2.12 (digest §1.6: R within "
               "4·10^-6 mm). R is reproduced only with the unsigned cosines (digest E1)."};
    out.tables.push_back(std::move(t));
  }
  return {};
}

}  // namespace volcomp::reproduce::dissertation
