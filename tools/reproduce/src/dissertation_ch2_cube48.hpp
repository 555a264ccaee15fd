// Internal to volcomp_reproduce: the printed rows of the dissertation's Tables 2.2-2.4 (laser-
// tracker axis lines of the 48 mm cube), defined in dissertation_ch2_cube48_data.cpp. These are
// not in tools/datasets (no command uses the 48 mm data), so they are typed here once.
#pragma once

namespace volcomp::reproduce::dissertation {

inline constexpr int kCube48Rows = 25;  // nodes 0, 2, …, 48 mm

struct Cube48Row {
  int line;              // seed 001 line of the row
  int commanded_mm[3];   // x_d, y_d, z_d
  const char* value[6];  // as printed: x_tr, y_tr, z_tr (mm), COS of the interval ending here
};

extern const Cube48Row kTable2_2[kCube48Rows];
extern const Cube48Row kTable2_3[kCube48Rows];
extern const Cube48Row kTable2_4[kCube48Rows];

}  // namespace volcomp::reproduce::dissertation
