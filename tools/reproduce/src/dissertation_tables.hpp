// Internal to volcomp_reproduce: the dissertation's (seed 001) tables, one producer per chapter,
// and the small helpers they share. ReproduceDissertation (dissertation.cpp) calls the producers
// in printed order. Printed numbers are typed as the printed text (decimal comma → point, "a·10^e"
// → "ae"), so a cell's tolerance is half a unit of its last printed digit unless a table's notes
// say why it is wider.
#pragma once

#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/vec3.hpp"
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::reproduce::dissertation {

inline constexpr const char* kSeed = "dissertation";

/// A printed number given as its printed text, e.g. "28.449109", "1.96e-5", "20e-4", "-0.002".
struct Printed {
  double value = 0.0;
  double half_unit = 0.0;  // half a unit in the last printed digit of the mantissa
};
/// Parses the text; a malformed literal is a programming error caught by the tests (value NaN).
Printed ParsePrinted(const char* text);

/// A cell comparing `printed_text` with `computed`, tolerance half a unit of its last digit
/// (times `tolerance_units_factor` when a table's notes document a wider one).
Cell MakeCell(std::string row,
              std::string column,
              std::string unit,
              const char* printed_text,
              double computed,
              std::string misprint = "",
              double tolerance_units_factor = 1.0);

/// "seed 001, line N (what)".
std::string SourceLine(int line, const std::string& what);

/// An empty table of this seed.
Table NewTable(const std::string& id, const std::string& title, const std::string& source);

/// Component i (0 = x, 1 = y, 2 = z) of v.
double Component(const model::Vec3& v, int i);

/// v rounded to 0.001 mm, as the Mathcad sheets display R before subtracting it (R0).
model::Vec3 RoundedToMicrometre(const model::Vec3& v_mm);

/// Three cells "<column>_x", "_y", "_z" of one printed vector; `tolerance` > 0 replaces the
/// half-unit one (the table's notes say why).
void AddVector(Table& table,
               const std::string& row,
               const std::string& column,
               const std::string& unit,
               const char* const (&printed)[3],
               const model::Vec3& computed,
               const std::string& misprint = "",
               double tolerance = 0.0);

/// A printed item the tool cannot reproduce, and why.
void AddNotReproduced(SeedReproduction& out,
                      const std::string& id,
                      const std::string& title,
                      const std::string& reason);

/// Producers: append the chapter's tables and its printed-but-not-reproducible items.
Expected<void> AddChapter2(SeedReproduction& out);
Expected<void> AddChapter3(SeedReproduction& out);
Expected<void> AddChapter4(SeedReproduction& out);
Expected<void> AddAppendixA(SeedReproduction& out);
Expected<void> AddAppendicesBVG(SeedReproduction& out);

}  // namespace volcomp::reproduce::dissertation
