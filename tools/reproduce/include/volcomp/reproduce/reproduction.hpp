// The seed documents' printed tables, recomputed by the tool's own evaluations: what
// `volcomp reproduce` prints and what its CI test checks. One printed number against the tool's
// is a Cell; a printed table (or a printed example's intermediate columns) is a Table. A printed
// value known to be wrong (a misprint recorded in the reference digests under
// ../shared/reference/) carries the explanation in `misprint` and is reported as such, never as
// a reproduction failure; an unexplained difference beyond the tolerance is a mismatch.
//
// Seeds (ids as `--seed` takes them):
//   gost27843     GOST 27843-88 (ISO 230-2) worked example, seed 000
//   iso230-6      ISO 230-6 diagonal displacement example, seed 003
//   iso230-7      GOST R ISO 230-7-2021 worked figures, seed 004
//   dissertation  Pimushkin 2023 (seed 001): Tables 2.x, 3.7–3.15, 4.1–4.10, Appendices Б/В/Г
//
// Producers never throw; a failure (e.g. the evaluation refused its input) is a Failure naming
// the table.
#pragma once

#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::reproduce {

/// One printed number against the tool's. difference = computed − printed.
struct Cell {
  std::string row;     // the printed row label, e.g. "x = 50 mm", "i = 3", "↑"
  std::string column;  // the printed column label, e.g. "A", "δx(x)", "x̄↑"
  std::string unit;    // "µm", "mm", "µrad", "arcsec", "" for a pure number
  double printed = 0.0;
  double computed = 0.0;
  /// |computed − printed| ≤ tolerance counts as reproduced: half a unit in the last printed
  /// digit unless the table's notes say why it is wider.
  double tolerance = 0.0;
  /// Empty, or why the printed value is known to be wrong (cite the digest's note).
  std::string misprint;
};

enum class CellVerdict {
  kReproduced,  // within tolerance (a flagged misprint that nevertheless agrees is kReproduced)
  kMisprint,    // beyond tolerance, explained by `misprint`
  kMismatch,    // beyond tolerance and unexplained: a reproduction failure
};

CellVerdict Judge(const Cell& cell);

/// "reproduced", "misprint" or "mismatch" (the JSON and text of `volcomp reproduce`).
const char* VerdictName(CellVerdict verdict);

/// One printed table (or a worked example's set of intermediate values).
struct Table {
  std::string seed;    // one of the seed ids above
  std::string id;      // what `--table` selects: "3.7", "4.10", "Б.1", "example", "A.2"
  std::string title;   // e.g. "Table 3.7: volumetric errors at the grid nodes, k = 1"
  std::string source;  // seed document and place, e.g. "seed 001, line 1795 (Table 3.7)"
  std::vector<Cell> cells;
  std::vector<std::string> notes;  // what the table leaves out and why, input choices made
};

/// A printed table that the tool cannot reproduce, and why (e.g. its inputs are not printed).
struct NotReproducible {
  std::string seed;
  std::string id;
  std::string title;
  std::string reason;
};

/// One seed's reproduction: its tables in printed order and the printed tables left out.
struct SeedReproduction {
  std::vector<Table> tables;
  std::vector<NotReproducible> not_reproduced;
};

/// What a reproduction amounts to: its cells by verdict and its tables.
struct Counts {
  int reproduced = 0;
  int misprints = 0;
  int mismatches = 0;
  int tables = 0;            // tables recomputed
  int not_reproducible = 0;  // printed tables listed as not reproducible
};
Counts Count(const SeedReproduction& reproduction);

/// Each seed's producer (one source file or a few per seed).
Expected<SeedReproduction> ReproduceGost27843();
Expected<SeedReproduction> ReproduceIso2306();
Expected<SeedReproduction> ReproduceIso2307();
Expected<SeedReproduction> ReproduceDissertation();

/// The seed ids in order: gost27843, iso230-6, iso230-7, dissertation.
const std::vector<std::string>& SeedIds();

/// All seeds (seed empty) or one, optionally only table `table_id` (empty: all its tables; the
/// not-reproduced list is then filtered the same way). Unknown seed or table id:
/// Error::kInvalidArgument naming it and listing the known ones. A producer's failure is
/// kInputInvalid, "seed ID: " and its message.
Expected<SeedReproduction> Reproduce(const std::string& seed, const std::string& table_id);

}  // namespace volcomp::reproduce
