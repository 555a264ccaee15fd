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

TEST(reproduce_dissertation, TableIdsAreUniqueAndPrintedNumbering) {
  std::set<std::string> ids;
  for (const Table& t : Dissertation().tables) EXPECT_TRUE(ids.insert(t.id).second) << t.id;
  for (const char* id :
       {"3.5", "3.6", "3.7", "3.8", "3.9", "3.10", "3.11", "3.12", "3.13", "3.14", "3.15", "А"})
    EXPECT_EQ(ids.count(id), 1u) << id;
}

// Chapter 3 digest (dissertation-ch3.md) §D4 errata, each beyond its cell's tolerance.
TEST(reproduce_dissertation, Chapter3ErrataAreFlaggedMisprints) {
  struct Expect {
    const char* table;
    const char* row;
    const char* column;
    double correct;  // the digest's recomputed value
    double tolerance;
  };
  const Expect errata[] = {
      {"3.12", "3/5/5", "δ−", 65.463946, 1e-6},        // D4.14: copy of δ+
      {"3.13", "10/20/14", "δ−/δ", 2.319, 5e-4},       // D4.14: copy of the δ+ % cell
      {"3.15", "k = 5", "δ−/δ", 21e-4, 0.5e-4},        // D4.14: printed 20·10^-4
      {"3.8", "10/20/14", "δ−/δ", 6.89e-7, 0.005e-7},  // D4.13: printed 69·10^-6
      {"3.8", "4/11/12", "δ−/δ", 5.62e-7, 0.005e-7},   // D4.13: printed 56·10^-6
      {"3.7", "3/5/5", "δ−/δ", 22e-6, 0.5e-6},         // D4.12: printed "20/δ"·10^-6
      {"3.15", "k = 5", "|E″|", 67.1, 0.05},           // D4.15: 1'17" should be 1'07"
  };
  for (const Expect& e : errata) {
    SCOPED_TRACE(std::string(e.table) + " " + e.row + " " + e.column);
    const Cell* c = FindCell(e.table, e.row, e.column);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(Judge(*c), CellVerdict::kMisprint);
    EXPECT_FALSE(c->misprint.empty());
    EXPECT_NEAR(c->computed, e.correct, e.tolerance);
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
  for (const char* id : {"3.2", "3.3", "3.4"}) EXPECT_EQ(ids.count(id), 1u) << id;
}

}  // namespace
}  // namespace volcomp::reproduce
