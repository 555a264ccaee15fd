// Internal to volcomp_reproduce: the printed rows of the dissertation's Tables 4.5-4.7 (the 2 mm
// refinement of Tables 3.2-3.4), defined in dissertation_ch4_fine_data.cpp.
#pragma once

namespace volcomp::reproduce::dissertation {

inline constexpr int kFineRows = 101;  // n = 0 … 100, position 2n mm

struct FineRow {
  int line;              // seed 001 line of the row
  const char* value[6];  // as printed: δ_ix, δ_iy, δ_iz (µm), ε_ix, ε_iy, ε_iz (µm/mm)
};

extern const FineRow kTable4_5[kFineRows];
extern const FineRow kTable4_6[kFineRows];
extern const FineRow kTable4_7[kFineRows];

}  // namespace volcomp::reproduce::dissertation
