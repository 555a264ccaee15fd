// ReproduceDissertation: the dissertation's (seed 001) printed tables in printed order, chapter by
// chapter (dissertation_ch2.cpp, _ch3.cpp, _ch4.cpp, _appendix_a.cpp, _appendices_bvg.cpp), and the
// shared helpers.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "dissertation_tables.hpp"

namespace volcomp::reproduce {
namespace dissertation {

Printed ParsePrinted(const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') return {NAN, NAN};
  // Digits after the decimal point of the mantissa, and the exponent.
  const char* point = std::strchr(text, '.');
  const char* exponent = std::strpbrk(text, "eE");
  int decimals = 0;
  if (point != nullptr) {
    const char* stop = exponent != nullptr ? exponent : text + std::strlen(text);
    decimals = static_cast<int>(stop - point - 1);
  }
  const int exp10 = exponent != nullptr ? std::atoi(exponent + 1) : 0;
  return {value, 0.5 * std::pow(10.0, exp10 - decimals)};
}

Cell MakeCell(std::string row,
              std::string column,
              std::string unit,
              const char* printed_text,
              double computed,
              std::string misprint,
              double tolerance_units_factor) {
  const Printed p = ParsePrinted(printed_text);
  Cell cell;
  cell.row = std::move(row);
  cell.column = std::move(column);
  cell.unit = std::move(unit);
  cell.printed = p.value;
  cell.computed = computed;
  cell.tolerance = p.half_unit * tolerance_units_factor;
  cell.misprint = std::move(misprint);
  return cell;
}

std::string SourceLine(int line, const std::string& what) {
  return "seed 001, line " + std::to_string(line) + " (" + what + ")";
}

Table NewTable(const std::string& id, const std::string& title, const std::string& source) {
  Table t;
  t.seed = kSeed;
  t.id = id;
  t.title = title;
  t.source = source;
  return t;
}

double Component(const model::Vec3& v, int i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }

model::Vec3 RoundedToMicrometre(const model::Vec3& v_mm) {
  return {std::round(v_mm.x * 1e3) / 1e3, std::round(v_mm.y * 1e3) / 1e3,
          std::round(v_mm.z * 1e3) / 1e3};
}

void AddVector(Table& table,
               const std::string& row,
               const std::string& column,
               const std::string& unit,
               const char* const (&printed)[3],
               const model::Vec3& computed,
               const std::string& misprint,
               double tolerance) {
  static const char* const kSuffix[3] = {"_x", "_y", "_z"};
  for (int i = 0; i < 3; ++i) {
    Cell c = MakeCell(row, column + kSuffix[i], unit, printed[i], Component(computed, i), misprint);
    if (tolerance > 0.0) c.tolerance = tolerance;
    table.cells.push_back(std::move(c));
  }
}

void AddNotReproduced(SeedReproduction& out,
                      const std::string& id,
                      const std::string& title,
                      const std::string& reason) {
  out.not_reproduced.push_back({kSeed, id, title, reason});
}

}  // namespace dissertation

Expected<SeedReproduction> ReproduceDissertation() {
  SeedReproduction out;
  VOLCOMP_TRY(dissertation::AddChapter2(out));
  VOLCOMP_TRY(dissertation::AddChapter3(out));
  VOLCOMP_TRY(dissertation::AddChapter4(out));
  VOLCOMP_TRY(dissertation::AddAppendixA(out));
  VOLCOMP_TRY(dissertation::AddAppendicesBVG(out));
  return out;
}

}  // namespace volcomp::reproduce
