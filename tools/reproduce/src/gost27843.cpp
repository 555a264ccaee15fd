// ReproduceGost27843(): the GOST 27843-88 worked example (seed 000, appendix) recomputed by the
// tool's positioning evaluation (metrology/positioning_eval.hpp) from the reconstructed readings,
// every printed column and result against its printed value (gost27843_printed.hpp).
#include <cmath>
#include <cstdio>
#include <string>

#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/reproduce/gost27843_printed.hpp"
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce {
namespace {

using gost27843::HalfLastDigit;
using gost27843::PrintedValue;

// Sums of two values already rounded to 0.01 µm (X̄ ± 3S, R_j, A, A↑, A↓) and 3S (rounded from
// the rounded S, either way) are compared to one unit of the last digit instead of half (the
// table notes say so).
constexpr double kRoundedSumTolerance = 0.01 + 1e-9;

struct KnownMisprint {
  int position;  // j, 0 for an overall result
  const char* column;
  const char* why;
};

// docs/metrology.md "The GOST 27843-88 worked example": every printed value that differs from its
// own printed readings and statistics, and why.
const KnownMisprint kMisprints[] = {
    {3, "X̄↑ + 3S↑", "printed 0,17: −4,18 + 3 × 1,339 = −0,163; the minus sign is lost"},
    {6, "S↓",
     "printed 1,996: the readings give 1,2961, and the printed X̄ ± 3S (−0,71, −8,49) and "
     "R_6 = 7,85 use 3S = 3,89, i.e. S = 1,296 (transcription slip)"},
    {6, "3S↓", "printed 3,98: a slip for 3,89 (3 × 1,2961 = 3,888), which X̄ ± 3S and R_6 use"},
    {7, "R",
     "printed 6,90 is 3S↑ + 3S↓ + |B| = 3,68 + 3,08 + 0,14 only; formula (8) takes the "
     "largest of that and 6S↑ = 7,36"},
    {10, "3S↓", "printed 4,96: the printed S = 1,649 gives 3S = 4,946 (4,95)"},
    {10, "X̄↓ + 3S↓",
     "printed 1,54: −3,46 + 4,946 = 1,486 (1,49); even the slipped 3S = 4,96 gives only 1,50"},
    {10, "R",
     "printed 12,26 = 5,92 + 4,96 + 1,38 with the slipped 3S↓ = 4,96; with 4,946 it is "
     "12,245 (12,25)"},
    {11, "S↓",
     "printed 1,884: OCR slip for 1,384/1,385; the printed 3S = 4,15, X̄ ± 3S = 2,61/−5,69 and "
     "R_11 = 13,49 need S ≈ 1,385 (the reconstructed readings give 1,3849)"},
    {11, "B", "printed −3,79: −5,32 − (−1,54) = −3,78 exactly (both means are multiples of 0,02)"},
    {0, "R↓",
     "printed 9,92 = 2 × the slipped 3S_10↓ = 4,96; the printed S_10↓ = 1,649 gives "
     "6S = 9,89"},
    {0, "B̄", "printed 1,53 without its sign: ΣB_j / 11 = −16,82 / 11 = −1,529"},
};

std::string MisprintOf(int position, const std::string& column) {
  for (const KnownMisprint& m : kMisprints) {
    if (m.position == position && column == m.column) return m.why;
  }
  return "";
}

std::string PositionRow(int j, double target_mm) {
  char text[48];
  std::snprintf(text, sizeof text, "j = %d (%.2f mm)", j, target_mm);
  return text;
}

Cell Printed(const std::string& row,
             const std::string& column,
             int position,
             const char* printed,
             double computed,
             bool rounded_sum) {
  Cell c;
  c.row = row;
  c.column = column;
  c.unit = "µm";
  c.printed = PrintedValue(printed);
  c.computed = computed;
  c.tolerance = rounded_sum ? kRoundedSumTolerance : HalfLastDigit(printed) + 1e-9;
  c.misprint = MisprintOf(position, column);
  return c;
}

Cell Location(const std::string& what, int printed_j, std::size_t computed_index) {
  Cell c;
  c.row = "results";
  c.column = "position j of " + what;
  c.printed = printed_j;
  c.computed = static_cast<double>(computed_index + 1);
  return c;
}

void AddColumn(Table& t,
               int j,
               const std::string& row,
               const char* arrow,
               const gost27843::PrintedColumn& p,
               const metrology::DirectionStats& s) {
  const std::string a = arrow;
  t.cells.push_back(Printed(row, "X̄" + a, j, p.mean, s.mean, false));
  t.cells.push_back(Printed(row, "S" + a, j, p.s, s.s, false));
  t.cells.push_back(Printed(row, "3S" + a, j, p.s3, 3.0 * s.s, true));
  t.cells.push_back(Printed(row, "X̄" + a + " + 3S" + a, j, p.upper, s.upper, true));
  t.cells.push_back(Printed(row, "X̄" + a + " − 3S" + a, j, p.lower, s.lower, true));
}

Expected<metrology::PositioningResult> Evaluate() {
  metrology::PositioningData data;
  data.source = "GOST 27843-88 worked example (seed 000)";
  std::size_t line = 0;
  for (int j = 1; j <= gost27843::kPositions; ++j) {
    for (const bool up : {true, false}) {
      for (int i = 1; i <= gost27843::kRuns; ++i) {
        metrology::PositioningReading r;
        r.target = gost27843::PrintedTable()[static_cast<std::size_t>(j - 1)].target_mm;
        r.direction = up ? metrology::Direction::kUp : metrology::Direction::kDown;
        r.run = i;
        r.deviation = gost27843::ReconstructedReading(j, up, i);
        r.line = ++line;
        data.readings.push_back(r);
      }
    }
  }
  VOLCOMP_TRY_ASSIGN(const metrology::PositioningSet set,
                     metrology::GroupReadings(data, metrology::GroupingOptions{}));
  metrology::EvaluationOptions options;
  options.standard = metrology::Standard::kGost27843;
  options.sigma = metrology::SigmaMethod::kFormula;
  return metrology::EvaluatePositioning(set, options);
}

std::vector<std::string> Notes() {
  std::vector<std::string> notes = {
      "Computed by `volcomp evaluate positioning` (GOST 27843-88, S by formula (5)) from the "
      "printed readings, with the readings damaged in transcription reconstructed "
      "(docs/metrology.md, \"Reconstruction\"); those columns reproduce their printed X̄ and S "
      "by construction, every other column as transcribed:"};
  for (const gost27843::ReadingEdit& e : gost27843::ReadingEdits()) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "  reading j = %d %s i = %d: printed %.1f, evaluated %.1f (%s)", e.position,
                  e.up ? "↑" : "↓", e.run, e.transcribed_um, e.reconstructed_um, e.why);
    notes.emplace_back(text);
  }
  notes.emplace_back(
      "Tolerance: half a unit in the last printed digit; X̄ ± 3S, R_j, A, A↑ and A↓ to 0.01 µm "
      "because the standard adds values already rounded to 0.01 µm (e.g. A = 6,89 − (−11,12)); "
      "3S to 0.01 µm because the print rounds it from the rounded S, up or down (3 × 0,832 = "
      "2,496 printed 2,49; 3 × 0,495 = 1,485 printed 1,49; 3 × 1,339 = 4,017 printed 4,01).");
  return notes;
}

}  // namespace

Expected<SeedReproduction> ReproduceGost27843() {
  Expected<metrology::PositioningResult> evaluated = Evaluate();
  if (!evaluated.ok()) return Fail(evaluated.error().Prefixed("GOST 27843-88 example"));
  const metrology::PositioningResult& r = *evaluated;
  if (r.positions.size() != static_cast<std::size_t>(gost27843::kPositions) || !r.bidirectional ||
      !r.accuracy || !r.accuracy_up || !r.accuracy_down || !r.repeatability ||
      !r.repeatability_up || !r.repeatability_down || !r.reversal_max || !r.reversal_mean) {
    return Fail(Error::kInputInvalid,
                "GOST 27843-88 example: the evaluation lacks a printed result");
  }
  Table t;
  t.seed = "gost27843";
  t.id = "example";
  t.title = "GOST 27843-88 appendix: worked example of the positioning accuracy evaluation";
  t.source = "seed 000, lines 405-505 (table lines 413-457, results 442-471 and 488-505)";
  t.notes = Notes();
  for (int j = 1; j <= gost27843::kPositions; ++j) {
    const gost27843::PrintedPosition& p =
        gost27843::PrintedTable()[static_cast<std::size_t>(j - 1)];
    const metrology::PositionStats& s = r.positions[static_cast<std::size_t>(j - 1)];
    if (!s.up || !s.down || !s.reversal || !s.repeatability_bidirectional) {
      return Fail(Error::kInputInvalid,
                  "GOST 27843-88 example: position " + std::to_string(j) + " lacks a direction");
    }
    const std::string row = PositionRow(j, p.target_mm);
    AddColumn(t, j, row, "↑", p.up, *s.up);
    AddColumn(t, j, row, "↓", p.down, *s.down);
    t.cells.push_back(Printed(row, "B", j, p.reversal, *s.reversal, false));
    t.cells.push_back(Printed(row, "R", j, p.repeatability, *s.repeatability_bidirectional, true));
  }
  const gost27843::PrintedResults& pr = gost27843::Results();
  const std::string results = "results";
  t.cells.push_back(Printed(results, "A", 0, pr.accuracy, r.accuracy->value, true));
  t.cells.push_back(
      Printed(results, "R_max", 0, pr.repeatability_max, r.repeatability->value, false));
  t.cells.push_back(Printed(results, "B_max", 0, pr.reversal_max, r.reversal_max->value, false));
  t.cells.push_back(Printed(results, "A↑", 0, pr.accuracy_up, r.accuracy_up->value, true));
  t.cells.push_back(Printed(results, "A↓", 0, pr.accuracy_down, r.accuracy_down->value, true));
  t.cells.push_back(
      Printed(results, "R↑", 0, pr.repeatability_up, r.repeatability_up->value, false));
  t.cells.push_back(
      Printed(results, "R↓", 0, pr.repeatability_down, r.repeatability_down->value, false));
  t.cells.push_back(Printed(results, "B̄", 0, pr.reversal_mean, *r.reversal_mean, false));
  t.cells.push_back(Location("max of A", pr.accuracy_max_position, r.accuracy->max.position));
  t.cells.push_back(Location("min of A", pr.accuracy_min_position, r.accuracy->min.position));
  t.cells.push_back(Location("R_max", pr.repeatability_max_position, r.repeatability->position));
  t.cells.push_back(Location("B_max", pr.reversal_max_position, r.reversal_max->position));
  t.cells.push_back(
      Location("max of A↑", pr.accuracy_up_max_position, r.accuracy_up->max.position));
  t.cells.push_back(
      Location("min of A↑", pr.accuracy_up_min_position, r.accuracy_up->min.position));
  t.cells.push_back(
      Location("max of A↓", pr.accuracy_down_max_position, r.accuracy_down->max.position));
  t.cells.push_back(
      Location("min of A↓", pr.accuracy_down_min_position, r.accuracy_down->min.position));
  t.cells.push_back(Location("R↑", pr.repeatability_up_position, r.repeatability_up->position));
  t.cells.push_back(Location("R↓", pr.repeatability_down_position, r.repeatability_down->position));

  SeedReproduction out;
  out.tables.push_back(std::move(t));
  out.not_reproduced.push_back(
      {"gost27843", "fig10", "Drawing 10: diagrams of X̄ ± 3S, B_j and R_j",
       "seed 000 line 486: the drawing is not in the seed (image missing); its values are the "
       "table's, reproduced above, and `evaluate positioning --report` draws it"});
  return out;
}

}  // namespace volcomp::reproduce
