// Raw printed tables of the dissertation (defined in s500_data.cpp); use s500.hpp.
#pragma once

#include "volcomp/model/dissertation.hpp"

namespace volcomp::datasets::data {

/// One row of Tables 3.2-3.4: position, three linear errors (µm), three angular errors (µm/mm).
struct ParametricRow {
  double position_mm;
  double delta_um[3];
  double eps_um_per_mm[3];
};

/// One row of Tables 2.6-2.8 / 2.10-2.12: commanded node, tracker reading (mm), printed cosines.
struct TrackerRow {
  double cmd_mm[3];
  double tracker_mm[3];
  double cos[3];
};

extern const ParametricRow kTable3_2[21];
extern const ParametricRow kTable3_3[29];
extern const ParametricRow kTable3_4[21];
extern const model::PointErrors kTable3_5;
extern const model::PointErrors kTable3_6;
extern const TrackerRow kTable2_6[17];
extern const TrackerRow kTable2_7[17];
extern const TrackerRow kTable2_8[17];
extern const TrackerRow kTable2_10[22];
extern const TrackerRow kTable2_11[22];
extern const TrackerRow kTable2_12[22];

}  // namespace volcomp::datasets::data
