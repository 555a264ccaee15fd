// Dissertation chapter 3 (seed 001 lines 1254-1917): Tables 3.5/3.6 (extremes of Tables 3.2-3.4),
// 3.7-3.13 (δ+, δ−, δ and the two % columns at six grid nodes for k = 1 … 1000) and 3.14/3.15
// (the hypothetical points M_max/M_min), recomputed with the "dissertation" formulation of
// tools/model (dissertation.hpp) on the printed Tables 3.2-3.6 compiled into tools/datasets.
// Errata cited as "digest D4.n" are items of ../shared/reference/dissertation-ch3.md §D4.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

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
constexpr double kArcsecPerRad = 180.0 * 3600.0 / kPi;

DissertationResult Evaluate(const PointErrors& p, double k, DissertationCase which) {
  DissertationOptions o;
  o.k = k;
  o.which = which;
  return DissertationError(p, o);
}

/// |δ±/δ − 1|·100, the printed "δ±/δ, %" (digest D2.7 item 7).
double PercentDifference(double second_um, double first_um) {
  return std::fabs(second_um / first_um - 1.0) * 100.0;
}

// ---- Tables 3.5 / 3.6 ------------------------------------------------------------------------

const char* const kErrorNames[2][3][3] = {
    {{"δ_xx", "δ_xy", "δ_xz"}, {"δ_yx", "δ_yy", "δ_yz"}, {"δ_zx", "δ_zy", "δ_zz"}},
    {{"ε_xx", "ε_xy", "ε_xz"}, {"ε_yx", "ε_yy", "ε_yz"}, {"ε_zx", "ε_zy", "ε_zz"}}};

// Printed Tables 3.5 (max) and 3.6 (min), seed lines 1748-1787, in the order δ_xx … ε_zz (rows
// i = axis, j = direction). The same numbers are compiled into tools/datasets (S500MaxErrors)
// as the inputs of Tables 3.14/3.15; here they are the printed results of a |·| max/min over the
// columns of Tables 3.2-3.4.
const char* const kPrintedMax[2][3][3] = {{{"42.666667", "14.500000", "4.033333"},
                                           {"12.700000", "78.850000", "3.833333"},
                                           {"4.133333", "14.633333", "11.833333"}},
                                          {{"0.035910", "0.032900", "0.061403"},
                                           {"0.031600", "0.011860", "0.024880"},
                                           {"0.014080", "0.011540", "0.005610"}}};
const char* const kPrintedMin[2][3][3] = {{{"0.466667", "1.266667", "0.200000"},
                                           {"0.233333", "6.883333", "0.033333"},
                                           {"0.116667", "2.650000", "0.133333"}},
                                          {{"0.027140", "0.026700", "0.000910"},
                                           {"0.019160", "0.007920", "0.007690"},
                                           {"0.000050", "0.009390", "0.003460"}}};

constexpr int kAxisRows[3] = {21, 29, 21};  // rows of Tables 3.2, 3.3, 3.4

Expected<void> AddExtremes(SeedReproduction& out) {
  // max/min of |value| over each column of the axis tables.
  double max_abs[2][3][3];
  double min_abs[2][3][3];
  for (int kind = 0; kind < 2; ++kind)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        max_abs[kind][i][j] = 0.0;
        min_abs[kind][i][j] = INFINITY;
      }
  for (int axis = 0; axis < 3; ++axis) {
    for (int n = 0; n < kAxisRows[axis]; ++n) {
      const int nx = axis == 0 ? n : 0, ny = axis == 1 ? n : 0, nz = axis == 2 ? n : 0;
      VOLCOMP_TRY_ASSIGN(const PointErrors p, datasets::S500PointErrorsAtNode(nx, ny, nz));
      for (int j = 0; j < 3; ++j) {
        const double v[2] = {std::fabs(p.delta_um[axis][j]), std::fabs(p.eps_um_per_mm[axis][j])};
        for (int kind = 0; kind < 2; ++kind) {
          max_abs[kind][axis][j] = std::fmax(max_abs[kind][axis][j], v[kind]);
          min_abs[kind][axis][j] = std::fmin(min_abs[kind][axis][j], v[kind]);
        }
      }
    }
  }
  const struct {
    const char* id;
    const char* title;
    int line;
    const char* const (*printed)[3][3];
    const double (*computed)[3][3];
  } tables[2] = {
      {"3.5", "Table 3.5: maximum parametric errors (by absolute value)", 1748, kPrintedMax,
       max_abs},
      {"3.6", "Table 3.6: minimum parametric errors (by absolute value)", 1769, kPrintedMin,
       min_abs},
  };
  for (const auto& t : tables) {
    Table table;
    table.seed = kSeed;
    table.id = t.id;
    table.title = t.title;
    table.source = SourceLine(t.line, std::string("Table ") + t.id);
    for (int kind = 0; kind < 2; ++kind)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          table.cells.push_back(
              MakeCell(kErrorNames[kind][i][j], t.id[2] == '5' ? "max |·|" : "min |·|",
                       kind == 0 ? "µm" : "µm/mm", t.printed[kind][i][j], t.computed[kind][i][j]));
    table.notes.push_back(
        "Computed: the largest/smallest absolute value of each column of the printed Tables "
        "3.2-3.4 (tools/datasets S500PointErrorsAtNode, every row of the axis).");
    out.tables.push_back(std::move(table));
  }
  return {};
}

// ---- Tables 3.7-3.13 -------------------------------------------------------------------------

struct Node {
  int nx, ny, nz;
  const char* label;  // as printed: "n_x/n_y/n_z (X/Y/Z mm)"
};
// The six grid nodes of every table, in printed order.
const Node kNodes[6] = {
    {3, 5, 5, "3/5/5 (60/50/50 mm)"},          {6, 17, 19, "6/17/19 (120/170/190 mm)"},
    {9, 13, 20, "9/13/20 (180/130/200 mm)"},   {7, 14, 11, "7/14/11 (140/140/110 mm)"},
    {10, 20, 14, "10/20/14 (200/200/140 mm)"}, {4, 11, 12, "4/11/12 (80/110/120 mm)"},
};

struct GridRow {
  const char* plus_um;
  const char* minus_um;
  const char* first_um;
  const char* plus_pct;
  const char* minus_pct;
  const char* misprint_minus_um;   // "" or why the printed δ− is wrong
  const char* misprint_minus_pct;  // "" or why the printed δ−/δ % is wrong
};

struct GridTable {
  const char* id;
  double k;
  int line;  // the table's title line; its rows are lines line+3 … line+8
  const char* title;
  GridRow rows[6];
};

const char* const kOcrFraction =
    "printed \"a/δ·10^-6\" is an OCR artefact of a·10^-6 (digest D4.12); the first row "
    "recomputes to 22·10^-6, the printed 20·10^-6 is wrong";
const char* const kTable38Exponent =
    "printed a·10^-6 should read 0.a·10^-6 (a digit shift, digest D4.13: recomputed 6.89·10^-7 "
    "and 5.62·10^-7)";

const GridTable kGridTables[] = {
    {"3.7",
     1.0,
     1795,
     "Table 3.7: volumetric error of the STAN S500 at six grid nodes (k = 1, implied)",
     {{"28.449109", "28.449111", "28.449118", "3e-5", "20e-6", "", kOcrFraction},
      {"53.955309", "53.95532", "53.955318", "1.7e-5", "4.7e-6", "", ""},
      {"49.983661", "49.983672", "49.983674", "2.5e-5", "4.1e-6", "", ""},
      {"49.419014", "49.419023", "49.419024", "1.96e-5", "1.2e-6", "", ""},
      {"64.809708", "64.809723", "64.809725", "2.5e-5", "2.65e-6", "", ""},
      {"39.485267", "39.485272", "39.485271", "1.13e-5", "2.3e-6", "", ""}}},
    {"3.8",
     0.5,
     1807,
     "Table 3.8: volumetric error of the STAN S500 at k = 0.5",
     {{"28.370336", "28.370337", "28.370339", "7e-6", "6e-6", "", ""},
      {"53.834281", "53.834284", "53.834284", "4.2e-6", "1.2e-6", "", ""},
      {"49.873753", "49.873756", "49.873756", "6.1e-6", "1.1e-6", "", ""},
      {"49.316609", "49.316611", "49.316611", "4.9e-6", "0.3e-6", "", ""},
      {"64.676917", "64.676921", "64.676922", "6.3e-6", "69e-6", "", kTable38Exponent},
      {"39.410534", "39.410536", "39.410535", "2.8e-6", "56e-6", "", kTable38Exponent}}},
    {"3.9",
     5.0,
     1817,
     "Table 3.9: volumetric error of the STAN S500 at k = 5",
     {{"29.152728", "29.152795", "29.152943", "7e-4", "5e-4", "", ""},
      {"54.947891", "54.948195", "54.948124", "4.2e-4", "1.3e-4", "", ""},
      {"50.88456", "50.884827", "50.884869", "6.1e-4", "0.8e-4", "", ""},
      {"50.265387", "50.265628", "50.265634", "4.9e-4", "0.11e-4", "", ""},
      {"65.901588", "65.901975", "65.902005", "6.3e-4", "0.45e-4", "", ""},
      {"40.118286", "40.118432", "40.118403", "2.9e-4", "0.73e-4", "", ""}}},
    {"3.10",
     10.0,
     1827,
     "Table 3.10: volumetric error of the STAN S500 at k = 10",
     {{"30.205137", "30.205458", "30.205997", "3e-3", "2e-3", "", ""},
      {"56.246911", "56.248181", "56.247862", "2e-3", "0.5e-3", "", ""},
      {"52.062477", "52.063603", "52.063726", "2e-3", "0.2e-3", "", ""},
      {"51.388448", "51.389474", "51.389454", "2e-3", "0.04e-3", "", ""},
      {"67.337389", "67.33902", "67.339079", "3e-3", "0.088e-3", "", ""},
      {"40.994111", "40.99475", "40.994601", "1e-3", "0.36e-3", "", ""}}},
    {"3.11",
     50.0,
     1837,
     "Table 3.11: volumetric error of the STAN S500 at k = 50",
     {{"43.405378", "43.419629", "43.424703", "45e-3", "12e-3", "", ""},
      {"68.49389", "68.533996", "68.520455", "39e-3", "20e-3", "", ""},
      {"63.141004", "63.177479", "63.173417", "51e-3", "6e-3", "", ""},
      {"62.460727", "62.495631", "62.488362", "44e-3", "12e-3", "", ""},
      {"81.113989", "81.167449", "81.158915", "55e-3", "11e-3", "", ""},
      {"50.699415", "50.723265", "50.714804", "30e-3", "17e-3", "", ""}}},
    {"3.12",
     100.0,
     1847,
     "Table 3.12: volumetric error of the STAN S500 at k = 100",
     {{"65.397367", "65.397367", "65.463165", "0.101", "0.001",
       "copy of the δ+ cell (digest D4.14): the δ− of this node is 65.463946; the printed "
       "0.001 % agrees with that value",
       ""},
      {"86.759787", "86.941687", "86.871489", "0.129", "0.081", "", ""},
      {"79.649106", "79.817301", "79.778319", "0.162", "0.049", "", ""},
      {"79.633549", "79.797071", "79.747421", "0.143", "0.062", "", ""},
      {"102.058171", "102.305887", "102.240111", "0.178", "0.064", "", ""},
      {"66.965766", "67.079324", "67.033176", "0.101", "0.069", "", ""}}},
    {"3.13",
     1000.0,
     1857,
     "Table 3.13: volumetric error of the STAN S500 at k = 1000",
     {{"517.530078", "524.862639", "521.793105", "0.817", "0.588", "", ""},
      {"475.646964", "496.68112", "486.839523", "2.299", "2.022", "", ""},
      {"431.566307", "451.695328", "442.758356", "2.528", "2.018", "", ""},
      {"455.011516", "474.508707", "465.605871", "2.275", "1.912", "", ""},
      {"555.782144", "585.310912", "572.045132", "2.843", "2.843", "",
       "copy of the δ+/δ % cell (digest D4.14): the δ−/δ difference of this node is 2.319 %"},
      {"431.729067", "444.850595", "438.680522", "1.585", "1.407", "", ""}}},
};

Expected<void> AddGridTables(SeedReproduction& out) {
  for (const GridTable& t : kGridTables) {
    Table table;
    table.seed = kSeed;
    table.id = t.id;
    table.title = t.title;
    table.source =
        SourceLine(t.line, std::string("Table ") + t.id + ", rows on lines " +
                               std::to_string(t.line + 3) + "-" + std::to_string(t.line + 8));
    for (int i = 0; i < 6; ++i) {
      const Node& node = kNodes[i];
      const GridRow& row = t.rows[i];
      VOLCOMP_TRY_ASSIGN(const PointErrors p,
                         datasets::S500PointErrorsAtNode(node.nx, node.ny, node.nz));
      const double plus = Evaluate(p, t.k, DissertationCase::kPlus).norm_um;
      const double minus = Evaluate(p, t.k, DissertationCase::kMinus).norm_um;
      const double first = Evaluate(p, t.k, DissertationCase::kFirstOrder).norm_um;
      // ±2·10^-6 µm (4 half-units): see the first note.
      table.cells.push_back(MakeCell(node.label, "δ+", "µm", row.plus_um, plus, "", 4.0));
      table.cells.push_back(
          MakeCell(node.label, "δ−", "µm", row.minus_um, minus, row.misprint_minus_um, 4.0));
      table.cells.push_back(MakeCell(node.label, "δ", "µm", row.first_um, first, "", 4.0));
      table.cells.push_back(MakeCell(node.label, "δ+/δ, %", "%", row.plus_pct,
                                     PercentDifference(plus, first), "", 2.0));
      table.cells.push_back(MakeCell(node.label, "δ−/δ, %", "%", row.minus_pct,
                                     PercentDifference(minus, first), row.misprint_minus_pct, 2.0));
    }
    table.notes.push_back(
        "Inputs: rows n_x, n_y, n_z of the printed Tables 3.2-3.4 (tools/datasets), k scales the "
        "nine angles only, r = (10, 10, 10) mm; δ+/δ− take every ± of eq. (3.5) as +/−, δ is the "
        "first order (3.10) — tools/model DissertationError (digest D2.7).");
    table.notes.push_back(
        "δ+, δ−, δ agree to ±2·10^-6 µm, not ±0.5·10^-6: the author's linear errors are multiples "
        "of 1/60 µm that Tables 3.2-3.4 print rounded to 6 decimals; with them snapped to n/60 "
        "the digest finds every value exact at 6 decimals (digest D4.11, D5).");
    table.notes.push_back(
        "The % columns are |δ±/δ − 1|·100 of the computed δ's (digest D2.7 item 7). The author "
        "rounded them inconsistently to 1-3 significant digits, often truncating (7.52·10^-6 "
        "printed 7·10^-6, 0.568·10^-3 printed 0.5·10^-3); the digest (D5) compares them only to "
        "their printed digits, so their tolerance is one unit (not half) of the last printed "
        "digit.");
    out.tables.push_back(std::move(table));
  }
  return {};
}

// ---- Tables 3.14 / 3.15 ----------------------------------------------------------------------

struct PointRow {
  double k;
  const char* label;
  const char* e_arcsec;  // |E″| printed as d° m' s", converted to arc-seconds
  const char* e_printed;
  const char* plus_um;
  const char* minus_um;
  const char* first_um;
  const char* plus_pct;
  const char* minus_pct;
  const char* misprint_e;
  const char* misprint_minus_pct;
};

const char* const kApproxAngle =
    "the printed |E″| values are approximations (digest D4.15: about 28″·k at M_max, 13.4″·k at "
    "M_min; not high-precision references)";

const PointRow kMaxRows[7] = {
    {0.5, "k = 0.5", "14", "0° 0' 14\"", "117.369557", "117.369555", "117.36956", "3e-6", "4.12e-6",
     "", ""},
    {1, "k = 1", "28", "0° 0' 28\"", "117.352224", "117.352219", "117.352238", "1.2e-5", "1.64e-5",
     "", ""},
    {5, "k = 5", "140", "0° 2' 20\"", "117.228659", "117.228546", "117.229021", "3.1e-4", "4.1e-4",
     "", ""},
    {10, "k = 10", "280", "0° 4' 40\"", "117.111999", "117.111629", "117.11349", "0.001", "0.002",
     "", ""},
    {50, "k = 50", "1400", "0° 23' 20\"", "117.688717", "117.695519", "117.733795", "0.038",
     "0.033", "", ""},
    {100, "k = 100", "2780", "0° 46' 20\"", "122.053765", "122.157189", "122.26615", "0.174",
     "0.089", kApproxAngle, ""},
    {1000, "k = 1000", "27800", "7° 43' 20\"", "429.035708", "469.562124", "454.539188", "5.611",
     "3.305", kApproxAngle, ""},
};
const PointRow kMinRows[7] = {
    {0.5, "k = 0.5", "7", "0° 0' 7\"", "7.845964", "7.845961", "7.845964", "3.319e-6", "26.5e-6",
     "", ""},
    {1, "k = 1", "14", "0° 0' 14\"", "7.743264", "7.743255", "7.743263", "0.95e-5", "10.47e-5",
     kApproxAngle, ""},
    {5, "k = 5", "77", "0° 1' 17\"", "7.149337", "7.149236", "7.149386", "6.88e-4", "20e-4",
     "1' 17\" should read 1' 07\" (67.1″, digest D4.15)",
     "recomputed 21·10^-4 (digest D4.14: rounding)"},
    {10, "k = 10", "134", "0° 2' 14\"", "7.068228", "7.068518", "7.068776", "0.008", "0.004", "",
     ""},
    {50, "k = 50", "671", "0° 11' 11\"", "20.88039", "20.930123", "20.908691", "0.135", "0.103", "",
     ""},
    {100, "k = 100", "1342", "0° 22' 22\"", "43.616936", "43.8251", "43.727767", "0.253", "0.223",
     "", ""},
    {1000, "k = 1000", "13397", "3° 43' 17\"", "454.713217", "475.777818", "465.552512", "2.328",
     "2.196", kApproxAngle, ""},
};

void AddPointTable(SeedReproduction& out,
                   const char* id,
                   const char* title,
                   int line,
                   const PointErrors& p,
                   const PointRow (&rows)[7]) {
  Table table;
  table.seed = kSeed;
  table.id = id;
  table.title = title;
  table.source = SourceLine(line, std::string("Table ") + id);
  for (const PointRow& r : rows) {
    const DissertationResult first = Evaluate(p, r.k, DissertationCase::kFirstOrder);
    const double plus = Evaluate(p, r.k, DissertationCase::kPlus).norm_um;
    const double minus = Evaluate(p, r.k, DissertationCase::kMinus).norm_um;
    const double e_arcsec = std::sqrt(first.a_rad * first.a_rad + first.b_rad * first.b_rad +
                                      first.c_rad * first.c_rad) *
                            kArcsecPerRad;
    // |E″| to ±0.5 % of its value (at least half a printed second): see the notes.
    Cell e = MakeCell(r.label, std::string("|E″| (printed ") + r.e_printed + ")", "arcsec",
                      r.e_arcsec, e_arcsec, r.misprint_e);
    e.tolerance = std::fmax(e.tolerance, 0.005 * e_arcsec);
    table.cells.push_back(std::move(e));
    table.cells.push_back(MakeCell(r.label, "δ+", "µm", r.plus_um, plus));
    table.cells.push_back(MakeCell(r.label, "δ−", "µm", r.minus_um, minus));
    table.cells.push_back(MakeCell(r.label, "δ", "µm", r.first_um, first.norm_um));
    table.cells.push_back(MakeCell(r.label, "δ+/δ, %", "%", r.plus_pct,
                                   PercentDifference(plus, first.norm_um), "", 2.0));
    table.cells.push_back(MakeCell(r.label, "δ−/δ, %", "%", r.minus_pct,
                                   PercentDifference(minus, first.norm_um), r.misprint_minus_pct,
                                   2.0));
  }
  table.notes.push_back(
      "Inputs: all 18 errors = the printed Table 3.5 (M_max) or 3.6 (M_min) magnitudes "
      "(tools/datasets), r = (10, 10, 10) mm, tools/model DissertationError.");
  table.notes.push_back(
      "|E″| is computed as the first-order ‖(A, B, C)‖ in arc-seconds. The author's values are "
      "approximate (digest D4.15), so they are compared to 0.5 % of the value (at least half a "
      "printed second); the % columns to one unit of their last printed digit (see Table 3.7).");
  out.tables.push_back(std::move(table));
}

}  // namespace

Expected<void> AddChapter3(SeedReproduction& out) {
  VOLCOMP_TRY(AddExtremes(out));
  VOLCOMP_TRY(AddGridTables(out));
  AddPointTable(out, "3.14", "Table 3.14: volumetric error of the STAN S500 at the point M_max",
                1875, datasets::S500MaxErrors(), kMaxRows);
  AddPointTable(out, "3.15", "Table 3.15: volumetric error of the STAN S500 at the point M_min",
                1891, datasets::S500MinErrors(), kMinRows);
  AddNotReproduced(out, "3.1",
                   "Table 3.1: the 21 parametric errors of a three-axis machining centre",
                   "names, symbols and instruments only: no numbers (seed line 1273)");
  AddNotReproduced(
      out, "3.2", "Table 3.2: parametric errors of axis O_x",
      "measured input data (Renishaw XL-80), compiled into tools/datasets as printed; nothing to "
      "recompute (seed line 1662)");
  AddNotReproduced(
      out, "3.3", "Table 3.3: parametric errors of axis O_y",
      "measured input data, compiled into tools/datasets; the row index printed \"24\" at 270 mm "
      "is row 27 (digest D4.8), rows 22-28 of the angular columns mirror rows 21-15 (D4.9) "
      "(seed line 1687)");
  AddNotReproduced(
      out, "3.4", "Table 3.4: parametric errors of axis O_z",
      "measured input data, compiled into tools/datasets; ε_zz = ε_zy − 0.015 µm/mm in every row "
      "(digest D4.10) (seed line 1721)");
  AddNotReproduced(
      out, "Fig. 3.41", "Figure 3.41: |ОП| over the working space, largest error 420 µm",
      "figure only, and the 420 µm comes from the method of refs. [53, 66], not described; the "
      "chapter's model gives at most 117.35 µm even at M_max (digest D4.19)");
  return {};
}

}  // namespace volcomp::reproduce::dissertation
