// GOST 27843-88 worked example as printed (gost27843_printed.hpp): typed from seed 000 lines
// 413-505 (readings, X̄, S, 3S, X̄ ± 3S, B_j, R_j and the results), misprints included.
#include "volcomp/reproduce/gost27843_printed.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

namespace volcomp::reproduce::gost27843 {

const std::array<PrintedPosition, kPositions>& PrintedTable() {
  // clang-format off
  static const std::array<PrintedPosition, kPositions> kTable = {{
    {0.00,
     {{-2.6, -1.6, -2.7, -1.8, 0.9}, "-1,92", "0,746", "2,24", "0,32", "-4,16"},
     {{2.3, 1.1, 3.2, 2.5, 1.5}, "2,12", "0,832", "2,49", "4,61", "-0,37"},
     "-4,04", "8,77"},
    {150.71,
     {{0.2, 0.7, 0.4, 1.8, 1.5}, "0,92", "0,698", "2,09", "3,01", "-1,17"},
     {{5.4, 4.6, 5.7, 5.4, 5.9}, "5,4", "0,495", "1,49", "6,89", "3,92"},
     "-4,48", "8,06"},
    {300.85,
     {{-5.0, -5.6, -4.8, -2.7, -2.8}, "-4,18", "1,339", "4,01", "0,17", "-8,19"},
     {{-1.5, -1.0, -0.6, -2.6, -0.8}, "-1,34", "0,76", "2,28", "0,94", "-3,62"},
     "-2,84", "9,13"},
    {450.33,
     {{0.6, 1.6, 0.5, 2.3, 2.3}, "1,46", "0,879", "2,64", "4,10", "-1,18"},
     {{2.4, 2.1, 3.6, 2.2, 2.9}, "2,64", "0,619", "1,86", "4,50", "0,78"},
     "-1,18", "5,68"},
    {601.11,
     {{-8.4, -7.4, -7.8, -6.1, -6.9}, "-7,32", "0,876", "2,63", "-4,69", "-9,95"},
     {{-9.0, -9.4, -8.1, -8.3, -7.8}, "-8,52", "0,661", "1,98", "-6,54", "-10,50"},
     "1,20", "5,81"},
    {750.31,
     {{-5.9, -3.7, -4.7, -3.4, -2.3}, "-3,80", "1,054", "3,16", "-0,64", "-6,96"},
     {{-5.9, -5.9, -4.0, -4.3, -2.9}, "-4,60", "1,996", "3,98", "-0,71", "-8,49"},
     "0,80", "7,85"},
    {901.55,
     {{-6.3, -5.1, -5.6, -4.1, -3.2}, "-4,86", "1,226", "3,68", "-1,18", "-8,54"},
     {{-5.8, -5.6, -4.7, -4.2, -3.3}, "-4,72", "1,028", "3,08", "-1,64", "-7,80"},
     "-0,14", "6,90"},
    {1050.02,
     {{-5.5, -3.6, -5.0, -2.3, -2.3}, "-3,74", "1,488", "4,46", "0,72", "-8,20"},
     {{-5.6, -4.8, -4.4, -4.4, -2.0}, "-4,24", "1,345", "4,03", "-0,20", "-8,27"},
     "0,50", "8,99"},
    {1201.90,
     {{-8.2, -5.9, -5.3, -4.6, -3.4}, "-5,68", "1,813", "5,44", "-0,24", "-11,12"},
     {{-6.1, -5.0, -4.8, -4.6, -2.0}, "-4,20", "1,632", "4,90", "0,70", "-9,10"},
     "-1,48", "11,82"},
    {1351.56,
     {{-7.4, -5.5, -5.4, -3.7, -2.2}, "-4,84", "1,973", "5,92", "1,08", "-10,76"},
     {{-5.6, -4.6, -2.9, -2.8, -1.4}, "-3,46", "1,649", "4,96", "1,54", "-8,41"},
     "-1,38", "12,26"},
    {1500.41,
     {{-7.8, -5.8, -5.6, -4.7, -2.7}, "-5,32", "1,851", "5,55", "0,23", "-10,87"},
     {{-3.0, -1.8, -0.2, 0.0, -2.7}, "-1,54", "1,884", "4,15", "2,61", "-5,69"},
     "-3,79", "13,49"},
  }};
  // clang-format on
  return kTable;
}

const std::vector<ReadingEdit>& ReadingEdits() {
  static const std::vector<ReadingEdit> kEdits = {
      {1, true, 5, 0.9, -0.9, "minus sign lost"},
      {3, false, 3, -0.6, -0.8, "the only one-reading edit giving the printed X̄ and S"},
      {6, true, 1, -5.9, -4.9, "the only one-reading edit giving the printed X̄ and S"},
      {9, true, 3, -5.3, -6.3, "the only one-reading edit giving the printed X̄ and S"},
      {9, false, 4, -4.6, -3.1, "the only one-reading edit giving the printed X̄ and S"},
      {11, false, 1, -3.0, -2.9, "with run 5: S = 1.3849, which the printed 3S, X̄ ± 3S, R need"},
      {11, false, 5, -2.7, -2.8, "the second edit of the pair with run 1"},
  };
  return kEdits;
}

double ReconstructedReading(int position, bool up, int run) {
  for (const ReadingEdit& e : ReadingEdits()) {
    if (e.position == position && e.up == up && e.run == run) return e.reconstructed_um;
  }
  const PrintedPosition& p = PrintedTable()[static_cast<std::size_t>(position - 1)];
  return (up ? p.up : p.down).readings_um[static_cast<std::size_t>(run - 1)];
}

const PrintedResults& Results() {
  // A = (X̄_2 + 3S_2)↓max − (X̄_9 − 3S_9)↑min; A↑ = (X̄_4 + 3S_4)↑ − (X̄_9 − 3S_9)↑;
  // A↓ = (X̄_2 + 3S_2)↓ − (X̄_5 − 3S_5)↓; R_max at 11, B_max at 2, R↑ and R↓ at 10.
  // clang-format off
  static const PrintedResults kResults = {
      "18,01", 2, 9,    // A (lines 442, 459, 496)
      "13,49", 11,      // R_max (lines 444, 457, 497)
      "4,48", 2,        // B_max (lines 446, 498)
      "15,22", 4, 9,    // A↑ (lines 448, 465, 499)
      "17,39", 2, 5,    // A↓ (lines 449, 467, 500)
      "11,84", 10,      // R↑ (lines 451, 469, 501)
      "9,92", 10,       // R↓ (lines 452, 471, 502)
      "1,53"};          // B̄ (lines 454, 505)
  // clang-format on
  return kResults;
}

namespace {

// The text after an optional sign: '-' (ASCII), '−' (U+2212) or '—' (U+2014, the seed's OCR).
const char* Unsigned(const char* text, bool* negative) {
  *negative = true;
  if (text[0] == '-') return text + 1;
  if (std::strncmp(text, "\xE2\x88\x92", 3) == 0 || std::strncmp(text, "\xE2\x80\x94", 3) == 0) {
    return text + 3;
  }
  *negative = false;
  return text;
}

}  // namespace

double PrintedValue(const char* text) {
  bool negative = false;
  std::string digits = Unsigned(text, &negative);
  for (char& c : digits) {
    if (c == ',') c = '.';
  }
  const double value = std::strtod(digits.c_str(), nullptr);
  return negative ? -value : value;
}

double HalfLastDigit(const char* text) {
  const char* comma = std::strchr(text, ',');
  double half = 0.5;
  if (comma != nullptr) {
    for (const char* c = comma + 1; *c >= '0' && *c <= '9'; ++c) half /= 10.0;
  }
  return half;
}

}  // namespace volcomp::reproduce::gost27843
