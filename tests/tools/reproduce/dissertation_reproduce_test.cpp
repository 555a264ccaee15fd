// `volcomp reproduce --seed dissertation`: every printed cell of the dissertation (seed 001) is
// reproduced by the tool's evaluations or is one of the misprints the reference digests record
// (../shared/reference/dissertation-ch1-2.md, -ch3.md, -ch4.md, their errata sections). The
// misprint oracle is the digests' errata, typed here by table/row/column, not the code's flags.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce {
namespace {

const SeedReproduction& Dissertation() {
  static const SeedReproduction r = [] {
    Expected<SeedReproduction> e = ReproduceDissertation();
    EXPECT_TRUE(e.ok()) << (e.ok() ? "" : e.error().message);
    return e.ok() ? *e : SeedReproduction{};
  }();
  return r;
}

const Table* FindTable(const std::string& id) {
  for (const Table& t : Dissertation().tables)
    if (t.id == id) return &t;
  return nullptr;
}

const Cell* FindCell(const std::string& table,
                     const std::string& row_prefix,
                     const std::string& column_prefix) {
  const Table* t = FindTable(table);
  if (t == nullptr) return nullptr;
  for (const Cell& c : t->cells)
    if (c.row.rfind(row_prefix, 0) == 0 && c.column.rfind(column_prefix, 0) == 0) return &c;
  return nullptr;
}

/// A misprint the digests record: the cell, and the value the digest recomputes.
struct Expect {
  const char* table;
  const char* row;     // prefix of the cell's row
  const char* column;  // prefix of the cell's column
  double correct;
  double tolerance;
};

void ExpectMisprint(const Expect& e) {
  SCOPED_TRACE(std::string(e.table) + " " + e.row + " " + e.column);
  const Cell* c = FindCell(e.table, e.row, e.column);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(Judge(*c), CellVerdict::kMisprint);
  EXPECT_FALSE(c->misprint.empty());
  EXPECT_NEAR(c->computed, e.correct, e.tolerance);
}

TEST(reproduce_dissertation, EveryCellReproducedOrAKnownMisprint) {
  int cells = 0;
  for (const Table& t : Dissertation().tables) {
    EXPECT_EQ(t.seed, "dissertation");
    EXPECT_FALSE(t.cells.empty()) << t.id;
    EXPECT_NE(t.source.find("seed 001, line "), std::string::npos) << t.id;
    for (const Cell& c : t.cells) {
      ++cells;
      EXPECT_TRUE(std::isfinite(c.printed) && std::isfinite(c.computed)) << t.id << " " << c.row;
      EXPECT_GT(c.tolerance, 0.0) << t.id << " " << c.row << " " << c.column;
      EXPECT_NE(Judge(c), CellVerdict::kMismatch)
          << "Table " << t.id << ", " << c.row << ", " << c.column << ": printed " << c.printed
          << ", computed " << c.computed << ", tolerance " << c.tolerance;
    }
  }
  EXPECT_GT(cells, 300);
}

TEST(reproduce_dissertation, MisprintsAreExactlyTheDigestsErrata) {
  // Counted from the digests' errata, so no flag can hide an unexplained difference:
  // E1 lists 5 + 4 + 5 + 6 + 3 + 9 dropped signs in Tables 2.6, 2.7, 2.8, 2.10, 2.11, 2.12; E3 the
  // Table 2.9 sum and its percentage; E2 Appendix В's G22. Ch. 3 D4.12-D4.15: 3.7 one % cell, 3.8
  // two, 3.12 δ−, 3.13 one % cell, 3.15 two |E″| and one % cell. Ch. 4: item 8 the three S of
  // step 1, item 13 two swapped q rows in 4.1 and one in 4.2, item 15 m and q of one 4.4 row,
  // item 19 fifteen q components of 4.9.
  const struct {
    const char* id;
    int misprints;
  } expected[] = {{"2.6", 5},  {"2.7", 4}, {"2.8", 5}, {"2.9", 2},  {"2.10", 6}, {"2.11", 3},
                  {"2.12", 9}, {"3.7", 1}, {"3.8", 2}, {"3.12", 1}, {"3.13", 1}, {"3.15", 3},
                  {"§4.3", 3}, {"4.1", 6}, {"4.2", 3}, {"4.4", 4},  {"4.9", 15}, {"В", 1}};
  int total = 0;
  for (const Table& t : Dissertation().tables) {
    int n = 0;
    for (const Cell& c : t.cells) n += Judge(c) == CellVerdict::kMisprint ? 1 : 0;
    int want = 0;
    for (const auto& e : expected)
      if (t.id == e.id) want = e.misprints;
    EXPECT_EQ(n, want) << "Table " << t.id;
    total += n;
  }
  EXPECT_EQ(total, 74);
}

TEST(reproduce_dissertation, TablesPerChapter) {
  // Chapter 2: 2.2-2.13 less the specification 2.1 = 12; chapter 3: 3.5-3.15 = 11 (+ Appendix А);
  // chapter 4: §4.3 and 4.1-4.10 = 11; Appendices Б, В, Г.
  int per_chapter[5] = {0, 0, 0, 0, 0};
  for (const Table& t : Dissertation().tables) {
    const char c = t.id[0];
    if (c == '2') ++per_chapter[0];
    if (c == '3') ++per_chapter[1];
    if (c == '4' || t.id == "§4.3") ++per_chapter[2];
    if (t.id == "А") ++per_chapter[3];
    if (t.id == "Б" || t.id == "В" || t.id == "Г") ++per_chapter[4];
  }
  EXPECT_EQ(per_chapter[0], 12);
  EXPECT_EQ(per_chapter[1], 11);
  EXPECT_EQ(per_chapter[2], 11);
  EXPECT_EQ(per_chapter[3], 1);
  EXPECT_EQ(per_chapter[4], 3);
}

TEST(reproduce_dissertation, TableIdsAreUniqueAndPrintedNumbering) {
  std::set<std::string> ids;
  for (const Table& t : Dissertation().tables) EXPECT_TRUE(ids.insert(t.id).second) << t.id;
  for (const char* id :
       {"3.5",  "3.6",  "3.7",  "3.8",  "3.9", "3.10", "3.11", "3.12", "3.13", "3.14",
        "3.15", "А",    "2.2",  "2.3",  "2.4", "2.5",  "2.6",  "2.7",  "2.8",  "2.9",
        "2.10", "2.11", "2.12", "2.13", "Б",   "В",    "Г",    "§4.3", "4.1",  "4.2",
        "4.3",  "4.4",  "4.5",  "4.6",  "4.7", "4.8",  "4.9",  "4.10"})
    EXPECT_EQ(ids.count(id), 1u) << id;
}

// Chapter 3 digest (dissertation-ch3.md) §D4 errata, each beyond its cell's tolerance.
TEST(reproduce_dissertation, Chapter3ErrataAreFlaggedMisprints) {
  const Expect errata[] = {
      {"3.12", "3/5/5", "δ−", 65.463946, 1e-6},        // D4.14: copy of δ+
      {"3.13", "10/20/14", "δ−/δ", 2.319, 5e-4},       // D4.14: copy of the δ+ % cell
      {"3.15", "k = 5", "δ−/δ", 21e-4, 0.5e-4},        // D4.14: printed 20·10^-4
      {"3.8", "10/20/14", "δ−/δ", 6.89e-7, 0.005e-7},  // D4.13: printed 69·10^-6
      {"3.8", "4/11/12", "δ−/δ", 5.62e-7, 0.005e-7},   // D4.13: printed 56·10^-6
      {"3.7", "3/5/5", "δ−/δ", 22e-6, 0.5e-6},         // D4.12: printed "20/δ"·10^-6
      {"3.15", "k = 5", "|E″|", 67.1, 0.05},           // D4.15: 1'17" should be 1'07"
  };
  for (const Expect& e : errata) ExpectMisprint(e);
}

// Chapter 4 digest (dissertation-ch4.md) §5 errata and its recomputed values (§2).
TEST(reproduce_dissertation, Chapter4ErrataAreFlaggedMisprints) {
  const Expect errata[] = {
      {"§4.3", "step 1", "S_x", 75.042131, 1e-5},     // item 8: shows the step-2 S
      {"4.1", "l = 0.1", "q_x", 49.820, 5e-4},        // item 13: rows swapped
      {"4.1", "l = 0.015", "q_z", 49.906, 5e-4},      // item 13
      {"4.2", "K = 1.5", "q_y", 49.813, 5e-4},        // item 13: repeats the swapped row
      {"4.4", "l = 0.015", "m", 175, 0},              // item 15: stop rule violated
      {"4.4", "l = 0.015", "q_tr_z", 107.451, 5e-4},  // item 15
      {"4.9", "110/170/185", "q_z", 185.887, 5e-4},   // item 19 (reading A)
      {"4.9", "130/140/106", "q_x", 129.545, 5e-4},   // item 19
  };
  for (const Expect& e : errata) ExpectMisprint(e);
  // Rows the digest reproduces (§2.11) stay reproduced, e.g. Table 4.9 at 50/50/50 (m = 20).
  for (const char* column : {"m", "q_x", "q_y", "q_z"}) {
    const Cell* c = FindCell("4.9", "50/50/50", column);
    ASSERT_NE(c, nullptr) << column;
    EXPECT_EQ(Judge(*c), CellVerdict::kReproduced) << column;
  }
}

TEST(reproduce_dissertation, Table4_10SumsAreThePrintedColumns) {
  // 0.342 + 0.436 + 0.289 + 0.132 + 0.377 + 0.240 + 0.282 = 2.098 (hand sum of lines 2800-2806);
  // 1 − 0.679/2.098 = 67.64 %, 1 − 0.208/2.098 = 90.09 %.
  const Cell* c = FindCell("4.10", "ΣΔ", "Δ_n");
  ASSERT_NE(c, nullptr);
  EXPECT_NEAR(c->computed, 2.098, 1e-9);
  c = FindCell("4.10", "improvement", "КМТПП");
  ASSERT_NE(c, nullptr);
  EXPECT_NEAR(c->computed, 90.086, 1e-3);
}

TEST(reproduce_dissertation, FineTablesCoverEveryPrintedRow) {
  // Tables 4.5-4.7: 101 rows (0-200 mm by 2) × 6 columns each; the first X row is Table 3.2's.
  for (const char* id : {"4.5", "4.6", "4.7"}) {
    const Table* t = FindTable(id);
    ASSERT_NE(t, nullptr) << id;
    EXPECT_EQ(t->cells.size(), 606u) << id;
  }
  const Cell* c = FindCell("4.5", "n = 1 (2 mm", "δ_xx");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->printed, -0.116667);  // seed line 2448
  // Hand interpolation: −0.466667 + (3.033333 + 0.466667)/10 = −0.116667.
  EXPECT_NEAR(c->computed, -0.116667, 1e-6);
}

// Chapter 1-2 digest (dissertation-ch1-2.md) §5.1 errata.
TEST(reproduce_dissertation, Chapter2AndAppendixErrataAreFlaggedMisprints) {
  const Expect errata[] = {
      // E1: cosines whose readings give a negative value, printed non-negative (a sample of 32).
      {"2.6", "x_d = 15", "COS_xy", -0.0009609, 1e-7},
      {"2.7", "y_d = 225", "COS_yz", -0.0004066, 1e-7},
      {"2.8", "z_d = 150", "COS_zy", -0.0000155, 1e-7},
      {"2.10", "x_d = 315", "COS_xz", -0.0002232, 1e-7},
      {"2.11", "y_d = 285", "COS_yz", -0.0000330, 1e-7},
      {"2.12", "z_d = 270", "COS_zy", -0.0000713, 1e-7},
      {"2.9", "ΣΔ", "Δ_dg", 1.636, 1e-9},                 // E3: the printed values add up to 1.636
      {"2.9", "improvement", "1 − ΣΔ_dg", 59.70, 0.005},  // E3
      {"В", "G", "G[2][2]", 0.99999975, 1e-7},            // E2: stray 9
  };
  for (const Expect& e : errata) ExpectMisprint(e);
  // E1 names 32 cells; every other cosine of the six tables is reproduced.
  int dropped = 0;
  for (const char* id : {"2.6", "2.7", "2.8", "2.10", "2.11", "2.12"}) {
    const Table* t = FindTable(id);
    ASSERT_NE(t, nullptr) << id;
    for (const Cell& c : t->cells) dropped += Judge(c) == CellVerdict::kMisprint ? 1 : 0;
  }
  EXPECT_EQ(dropped, 32);
  // The 48 mm tables keep their signs (E1): Table 2.2 row 8, COS_xy printed −0.0005513.
  const Cell* c = FindCell("2.2", "x_d = 8", "COS_xy");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->printed, -0.0005513);
  EXPECT_EQ(Judge(*c), CellVerdict::kReproduced);
}

TEST(reproduce_dissertation, AppendicesGiveThePrintedCommands) {
  // Appendices Б, В, Г print q = (129.902, 139.929, 105.949), (129.768, 139.921, 105.927),
  // (129.844, 139.89, 105.891) (seed lines 3128, 3176, 3236).
  const struct {
    const char* table;
    double x;
  } commands[] = {{"Б", 129.902}, {"В", 129.768}, {"Г", 129.844}};
  for (const auto& q : commands) {
    const Cell* c = FindCell(q.table, "q (command)", "q_x");
    ASSERT_NE(c, nullptr) << q.table;
    EXPECT_EQ(c->printed, q.x);
    EXPECT_EQ(Judge(*c), CellVerdict::kReproduced) << q.table;
  }
}

TEST(reproduce_dissertation, Chapter3PrintedValuesAreTheSeeds) {
  // Spot checks typed from the seed (lines 1798, 1902, 3031): the printed side is the document's.
  const Cell* c = FindCell("3.7", "3/5/5", "δ");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->column, "δ+");
  EXPECT_EQ(c->printed, 28.449109);
  c = FindCell("3.15", "k = 1000", "δ−");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->printed, 475.777818);
  c = FindCell("А", "p (all", "δp");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->printed, 54.789011);
  EXPECT_EQ(Judge(*c), CellVerdict::kReproduced);
}

TEST(reproduce_dissertation, NotReproducedListNamesItsReasons) {
  const SeedReproduction& r = Dissertation();
  std::set<std::string> ids;
  for (const NotReproducible& n : r.not_reproduced) {
    EXPECT_EQ(n.seed, "dissertation");
    EXPECT_GT(n.reason.size(), 20u) << n.id;
    ids.insert(n.id);
  }
  for (const char* id : {"3.2", "3.3", "3.4", "4.8", "4.10", "2.1"})
    EXPECT_EQ(ids.count(id), 1u) << id;
}

}  // namespace
}  // namespace volcomp::reproduce
