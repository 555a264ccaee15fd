// Angle-sampled displacement data of an ISO 230-7 error-motion test, read from CSV:
//
//   rev,angle_deg,x_um,y_um,x2_um,y2_um,z_um,face_um
//   1,0.0,0.512,-0.033,...
//
// - rev: revolution index (integer); the rows of one revolution are contiguous;
// - angle_deg: spindle/table angle θ in [0, 360), strictly increasing within a revolution and the
//   same set of angles in every revolution (whole revolutions only);
// - channels, µm, each optional but at least one present:
//   x_um, y_um    radial displacement of the artefact along +X / +Y at the first axial plane;
//   x2_um, y2_um  the same at a second plane a distance L further along the axis (tilt);
//   z_um          axial displacement (along the axis average line);
//   face_um       face displacement at radius R.
// Sign convention (ISO 230-7 A.7.2): positive when the artefact moves away from the sensor, i.e.
// the channel gives the displacement of the artefact centre along +X, +Y or +Z.
// Other columns are ignored.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "volcomp/metrology/error_motion.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

/// Channel column names in the order above.
const std::vector<std::string>& RotaryChannelNames();

struct RotaryRecord {
  std::string source;
  std::vector<double> angle_deg;                // the N angles of a revolution
  std::vector<long long> revs;                  // revolution labels in file order
  std::map<std::string, Revolutions> channels;  // channel name -> u[k][j], µm
  bool equally_spaced = true;                   // angles equally spaced over the full turn
};

/// A failure (kInputInvalid) naming the line for: missing rev/angle_deg column, no channel
/// column, bad numbers, angles out of [0, 360) or not increasing, a revolution split in two parts,
/// a revolution whose angles differ from the first one's, fewer than 4 angles per revolution.
Expected<RotaryRecord> ReadRotaryCsv(const tools::CsvTable& table);

}  // namespace volcomp::metrology
