// volcomp_reproduce (reproduction.hpp): Judge on hand-made cells, the seed/table selection and
// its refusals, and the GOST 27843-88 worked example against the printed document: every cell
// reproduced or a known misprint, and the misprints found by reading the print (the list below,
// from docs/metrology.md) are exactly the cells flagged, each with its value worked by hand.
#include "volcomp/reproduce/reproduction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>

#include "sample_path.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/reproduce/gost27843_printed.hpp"

namespace volcomp::reproduce {
namespace {

Cell Made(double printed, double computed, double tolerance, std::string misprint = "") {
  Cell c;
  c.row = "r";
  c.column = "c";
  c.printed = printed;
  c.computed = computed;
  c.tolerance = tolerance;
  c.misprint = std::move(misprint);
  return c;
}

TEST(Reproduce, JudgeVerdictsOnHandMadeCells) {
  EXPECT_EQ(Judge(Made(1.25, 1.5, 0.25)), CellVerdict::kReproduced);  // exactly at tolerance
  EXPECT_EQ(Judge(Made(1.25, 1.0, 0.25)), CellVerdict::kReproduced);
  EXPECT_EQ(Judge(Made(1.25, 1.5625, 0.25)), CellVerdict::kMismatch);
  EXPECT_EQ(Judge(Made(1.25, 1.5625, 0.25, "slip")), CellVerdict::kMisprint);
  // A flagged misprint that nevertheless agrees is reproduced.
  EXPECT_EQ(Judge(Made(1.25, 1.25, 0.0, "slip")), CellVerdict::kReproduced);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Judge(Made(1.0, nan, 1e9)), CellVerdict::kMismatch);
  EXPECT_EQ(Judge(Made(nan, 1.0, 1e9, "x")), CellVerdict::kMisprint);
  EXPECT_STREQ(VerdictName(CellVerdict::kReproduced), "reproduced");
  EXPECT_STREQ(VerdictName(CellVerdict::kMisprint), "misprint");
  EXPECT_STREQ(VerdictName(CellVerdict::kMismatch), "mismatch");
}

TEST(Reproduce, CountGroupsCellsByVerdict) {
  SeedReproduction s;
  Table t;
  t.cells = {Made(1, 1, 0), Made(1, 2, 0), Made(1, 2, 0, "why"), Made(1, 3, 0, "why")};
  s.tables = {t, Table{}};
  s.not_reproduced = {NotReproducible{}};
  const Counts n = Count(s);
  EXPECT_EQ(n.tables, 2);
  EXPECT_EQ(n.reproduced, 1);
  EXPECT_EQ(n.misprints, 2);
  EXPECT_EQ(n.mismatches, 1);
  EXPECT_EQ(n.not_reproducible, 1);
}

TEST(Reproduce, SeedIdsInOrder) {
  EXPECT_EQ(SeedIds(),
            (std::vector<std::string>{"gost27843", "iso230-6", "iso230-7", "dissertation"}));
}

TEST(Reproduce, UnknownSeedIsRefusedListingTheKnownOnes) {
  const auto r = Reproduce("nonsense", "");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kInvalidArgument);
  for (const char* id : {"nonsense", "gost27843", "iso230-6", "iso230-7", "dissertation"}) {
    EXPECT_NE(r.error().message.find(id), std::string::npos) << r.error().message;
  }
}

TEST(Reproduce, UnknownTableIsRefusedListingTheKnownOnes) {
  auto r = Reproduce("gost27843", "9.9");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kInvalidArgument);
  EXPECT_NE(r.error().message.find("'9.9'"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("gost27843:example"), std::string::npos) << r.error().message;
  // A table of another seed is not one of this seed's.
  r = Reproduce("gost27843", "F");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kInvalidArgument);
}

TEST(Reproduce, SelectionBySeedAndTable) {
  const SeedReproduction gost = Reproduce("gost27843", "example").value();
  ASSERT_EQ(gost.tables.size(), 1u);
  EXPECT_EQ(gost.tables[0].seed, "gost27843");
  EXPECT_TRUE(gost.not_reproduced.empty());
  // Without a seed, a table id selects it in whichever seed has it.
  const SeedReproduction f = Reproduce("", "F").value();
  ASSERT_EQ(f.tables.size(), 1u);
  EXPECT_EQ(f.tables[0].seed, "iso230-7");
  // A not-reproducible entry is selected the same way.
  const SeedReproduction h1 = Reproduce("iso230-7", "H.1").value();
  EXPECT_TRUE(h1.tables.empty());
  ASSERT_EQ(h1.not_reproduced.size(), 1u);
  EXPECT_NE(h1.not_reproduced[0].reason.find("1932"), std::string::npos);
  // All seeds: each seed's tables and entries, in seed order.
  const SeedReproduction all = Reproduce("", "").value();
  const Counts n = Count(all);
  const Counts one = Count(Reproduce("gost27843", "").value());
  EXPECT_GE(n.reproduced, one.reproduced);
  EXPECT_EQ(all.tables.front().seed, "gost27843");
}

TEST(Reproduce, Iso2306PrintsNoNumericTableAndSaysWhy) {
  const SeedReproduction r = Reproduce("iso230-6", "").value();
  EXPECT_TRUE(r.tables.empty());
  ASSERT_FALSE(r.not_reproduced.empty());
  for (const NotReproducible& n : r.not_reproduced) {
    EXPECT_EQ(n.seed, "iso230-6");
    EXPECT_NE(n.reason.find("seed 003 line"), std::string::npos) << n.reason;
  }
}

// ISO 230-7 Annex F prints 0,6 (F.2, F.3) and 1,4 (F.7).
TEST(Reproduce, Iso2307AnnexFFactors) {
  const SeedReproduction r = Reproduce("iso230-7", "F").value();
  ASSERT_EQ(r.tables.size(), 1u);
  ASSERT_EQ(r.tables[0].cells.size(), 3u);
  const double printed[3] = {0.6, 0.6, 1.4};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(r.tables[0].cells[i].printed, printed[i]);
    EXPECT_NEAR(r.tables[0].cells[i].computed, printed[i], 1e-12);
    EXPECT_EQ(Judge(r.tables[0].cells[i]), CellVerdict::kReproduced);
  }
}

TEST(ReproduceGost27843, PrintedTextValues) {
  using gost27843::HalfLastDigit;
  using gost27843::PrintedValue;
  EXPECT_DOUBLE_EQ(PrintedValue("-1,92"), -1.92);
  EXPECT_DOUBLE_EQ(PrintedValue("\xE2\x80\x94"
                                "0,64"),
                   -0.64);  // the seed's "—0,64"
  EXPECT_DOUBLE_EQ(PrintedValue("\xE2\x88\x92"
                                "3,79"),
                   -3.79);
  EXPECT_DOUBLE_EQ(PrintedValue("13,49"), 13.49);
  EXPECT_DOUBLE_EQ(HalfLastDigit("5,4"), 0.05);
  EXPECT_DOUBLE_EQ(HalfLastDigit("0,76"), 0.005);
  EXPECT_DOUBLE_EQ(HalfLastDigit("0,746"), 0.0005);
}

// The typing of the print checked against the print itself: every column's transcribed readings
// give its printed X̄ (to the printed digit), except the columns the reconstruction edits.
TEST(ReproduceGost27843, TranscribedReadingsGiveThePrintedMeans) {
  std::set<std::pair<int, bool>> edited;
  for (const auto& e : gost27843::ReadingEdits()) edited.insert({e.position, e.up});
  for (int j = 1; j <= gost27843::kPositions; ++j) {
    const auto& p = gost27843::PrintedTable()[static_cast<std::size_t>(j - 1)];
    for (const bool up : {true, false}) {
      const auto& col = up ? p.up : p.down;
      double sum = 0.0, sum_reconstructed = 0.0;
      for (int i = 1; i <= gost27843::kRuns; ++i) {
        sum += col.readings_um[static_cast<std::size_t>(i - 1)];
        sum_reconstructed += gost27843::ReconstructedReading(j, up, i);
      }
      SCOPED_TRACE("j = " + std::to_string(j) + (up ? " up" : " down"));
      const double printed = gost27843::PrintedValue(col.mean);
      EXPECT_NEAR(sum_reconstructed / 5, printed, gost27843::HalfLastDigit(col.mean));
      // 6↑ and 9↑/9↓ change the sum; 1↑ (sign) too; 3↓ and 11↓ keep it within the print.
      if (edited.count({j, up}) == 0) {
        EXPECT_NEAR(sum / 5, printed, gost27843::HalfLastDigit(col.mean));
      }
    }
  }
}

// The readings the reproduction evaluates are those of samples/metrology/gost27843_example_long.csv
// (which `evaluate positioning` documents in docs/metrology.md).
TEST(ReproduceGost27843, ReconstructedReadingsAreTheSampleFile) {
  const auto table =
      tools::CsvTable::ReadFile(testing::SamplePath("metrology/gost27843_example_long.csv"))
          .value();
  const metrology::PositioningData data = metrology::ReadPositioningCsv(table).value();
  ASSERT_EQ(data.readings.size(), 110u);
  for (const metrology::PositioningReading& r : data.readings) {
    int j = 0;
    for (int k = 1; k <= gost27843::kPositions; ++k) {
      if (std::fabs(gost27843::PrintedTable()[static_cast<std::size_t>(k - 1)].target_mm -
                    r.target) < 1e-9) {
        j = k;
      }
    }
    ASSERT_NE(j, 0) << r.target;
    EXPECT_DOUBLE_EQ(
        gost27843::ReconstructedReading(j, r.direction == metrology::Direction::kUp, r.run),
        r.deviation)
        << "j = " << j << " run " << r.run;
  }
}

const Cell* Find(const Table& t, const std::string& row_start, const std::string& column) {
  for (const Cell& c : t.cells) {
    if (c.row.rfind(row_start, 0) == 0 && c.column == column) return &c;
  }
  return nullptr;
}

TEST(ReproduceGost27843, EveryCellReproducedOrAKnownMisprint) {
  const SeedReproduction r = ReproduceGost27843().value();
  ASSERT_EQ(r.tables.size(), 1u);
  const Table& t = r.tables[0];
  // 11 positions × (5 columns × 2 directions + B + R), 8 results, 10 printed locations.
  EXPECT_EQ(t.cells.size(), 11u * 12u + 8u + 10u);
  // The printed values that contradict the print's own readings and statistics
  // (docs/metrology.md, "The GOST 27843-88 worked example"), found by reading the document.
  const std::set<std::pair<std::string, std::string>> known = {
      {"j = 3 ", "X̄↑ + 3S↑"}, {"j = 6 ", "S↓"},  {"j = 6 ", "3S↓"},       {"j = 7 ", "R"},
      {"j = 10 ", "3S↓"},     {"j = 10 ", "R"},  {"j = 10 ", "X̄↓ + 3S↓"}, {"j = 11 ", "S↓"},
      {"j = 11 ", "B"},       {"results", "R↓"}, {"results", "B̄"}};
  int misprints = 0;
  for (const Cell& c : t.cells) {
    SCOPED_TRACE(c.row + " | " + c.column);
    const CellVerdict v = Judge(c);
    EXPECT_NE(v, CellVerdict::kMismatch) << c.printed << " vs " << c.computed;
    if (v == CellVerdict::kMisprint) {
      ++misprints;
      bool listed = false;
      for (const auto& k : known)
        listed = listed || (c.row.rfind(k.first, 0) == 0 && c.column == k.second);
      EXPECT_TRUE(listed);
    }
  }
  EXPECT_EQ(misprints, static_cast<int>(known.size()));
}

TEST(ReproduceGost27843, KnownMisprintsAreFlaggedWithTheirHandWorkedValues) {
  const Table t = ReproduceGost27843().value().tables.at(0);
  struct Expect {
    const char* row;
    const char* column;
    double printed;
    double worked;  // from the printed readings / statistics, by hand
    double within;
  };
  const Expect cases[] = {
      // R↓ = 6 × printed S_10↓ 1,649 = 9,894 (the print doubles a slipped 3S = 4,96).
      {"results", "R↓", 9.92, 6 * 1.649, 0.003},
      // B̄ = ΣB_j / 11 with B_11 = −5,32 + 1,54 = −3,78: −16,82 / 11.
      {"results", "B̄", 1.53, -16.82 / 11, 1e-9},
      // X̄_3↑ + 3S_3↑ = −4,18 + 3 × 1,339 = −0,163 (printed without its sign); S to ±0,0005.
      {"j = 3 ", "X̄↑ + 3S↑", 0.17, -4.18 + 3 * 1.339, 0.002},
      // R_7 = 6S_7↑ = 6 × 1,226 = 7,356, larger than the printed 3S + 3S + |B| = 6,90.
      {"j = 7 ", "R", 6.90, 6 * 1.226, 0.001},
      // B_11 = −5,32 − (−1,54).
      {"j = 11 ", "B", -3.79, -5.32 + 1.54, 1e-9},
      // S_11↓: the print's own 3S = 4,15 gives S = 1,383; printed "1,884".
      {"j = 11 ", "S↓", 1.884, 4.15 / 3, 0.003},
      // S_6↓: the print's own X̄ + 3S = −0,71 with X̄ = −4,60 gives S = 1,297; printed "1,996".
      {"j = 6 ", "S↓", 1.996, (-0.71 + 4.60) / 3, 0.003},
  };
  for (const Expect& e : cases) {
    SCOPED_TRACE(std::string(e.row) + " | " + e.column);
    const Cell* c = Find(t, e.row, e.column);
    ASSERT_NE(c, nullptr);
    EXPECT_DOUBLE_EQ(c->printed, e.printed);
    EXPECT_NEAR(c->computed, e.worked, e.within);
    EXPECT_EQ(Judge(*c), CellVerdict::kMisprint);
    EXPECT_FALSE(c->misprint.empty());
  }
}

TEST(ReproduceGost27843, ResultsAndTheirPrintedPositions) {
  const Table t = ReproduceGost27843().value().tables.at(0);
  // A = 5,40 + 3·0,49497 − (−5,68 − 3·1,81301) = 18,0039 (printed 18,01 from rounded terms).
  const Cell* a = Find(t, "results", "A");
  ASSERT_NE(a, nullptr);
  EXPECT_NEAR(a->computed, 18.0039, 1e-4);
  EXPECT_EQ(Judge(*a), CellVerdict::kReproduced);
  // Printed subscripts: A between j = 2 and j = 9, R_max at 11, B_max at 2, R↑/R↓ at 10.
  const std::pair<const char*, double> where[] = {
      {"position j of max of A", 2}, {"position j of min of A", 9}, {"position j of R_max", 11},
      {"position j of B_max", 2},    {"position j of R↑", 10},      {"position j of R↓", 10}};
  for (const auto& w : where) {
    const Cell* c = Find(t, "results", w.first);
    ASSERT_NE(c, nullptr) << w.first;
    EXPECT_DOUBLE_EQ(c->computed, w.second) << w.first;
  }
}

}  // namespace
}  // namespace volcomp::reproduce
