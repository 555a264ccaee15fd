// ReproduceDissertation: the dissertation's (seed 001) printed tables in printed order, chapter by
// chapter (dissertation_ch2.cpp, _ch3.cpp, _ch4.cpp, _appendices.cpp), and the shared helpers.
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
