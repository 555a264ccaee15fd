// The worked example of GOST 27843-88 (appendix "Пример оценки результатов проверки точности
// позиционирования", seed 000 lines 405-505) as printed: the readings as transcribed, the
// reconstruction of the readings damaged in transcription, and every printed column and result
// exactly as printed (text with its decimal comma, so the last printed digit is known).
// One definition: `volcomp reproduce --seed gost27843` compares these with the tool's evaluation;
// the analysis of the misprints is in docs/metrology.md, "The GOST 27843-88 worked example".
#pragma once

#include <array>
#include <vector>

namespace volcomp::reproduce::gost27843 {

inline constexpr int kPositions = 11;  // j = 1..11
inline constexpr int kRuns = 5;        // i = 1..5 approaches per direction

/// One direction's printed column at a position: readings X_ij (µm, as transcribed from the seed,
/// damage included) and the printed statistics as printed text ("−1,92", "0,76").
struct PrintedColumn {
  std::array<double, kRuns> readings_um;
  const char* mean;   // X̄_j
  const char* s;      // S_j
  const char* s3;     // 3S_j
  const char* upper;  // X̄_j + 3S_j
  const char* lower;  // X̄_j − 3S_j
};

struct PrintedPosition {
  double target_mm;  // P_j
  PrintedColumn up;
  PrintedColumn down;
  const char* reversal;       // B_j
  const char* repeatability;  // R_j, "the largest of 6S↑, 6S↓, 3S↑ + 3S↓ + |B|" (formula (8))
};

/// The printed table, positions 1..11 (seed 000 lines 413-457).
const std::array<PrintedPosition, kPositions>& PrintedTable();

/// A reading changed so that its column reproduces BOTH its printed X̄_j and S_j (docs/metrology.md
/// "Reconstruction"): the transcribed value and the reconstructed one.
struct ReadingEdit {
  int position;  // j, 1-based
  bool up;       // ↑ (else ↓)
  int run;       // i, 1-based
  double transcribed_um;
  double reconstructed_um;
  const char* why;
};
const std::vector<ReadingEdit>& ReadingEdits();

/// The readings the tool evaluates: the transcribed readings with ReadingEdits() applied.
double ReconstructedReading(int position, bool up, int run);

/// The printed overall results (seed 000 lines 442-505), as printed text, with the printed position
/// (j, 1-based) of each extreme.
struct PrintedResults {
  const char* accuracy;  // A
  int accuracy_max_position, accuracy_min_position;
  const char* repeatability_max;  // R_max
  int repeatability_max_position;
  const char* reversal_max;  // B_max
  int reversal_max_position;
  const char* accuracy_up;  // A↑
  int accuracy_up_max_position, accuracy_up_min_position;
  const char* accuracy_down;  // A↓
  int accuracy_down_max_position, accuracy_down_min_position;
  const char* repeatability_up;  // R↑
  int repeatability_up_position;
  const char* repeatability_down;  // R↓
  int repeatability_down_position;
  const char* reversal_mean;  // B̄
};
const PrintedResults& Results();

/// The value of printed text: decimal comma, a leading '-' or '−' or '—'.
double PrintedValue(const char* text);
/// Half a unit in the last printed digit of `text` ("0,76" → 0.005, "5,4" → 0.05).
double HalfLastDigit(const char* text);

}  // namespace volcomp::reproduce::gost27843
