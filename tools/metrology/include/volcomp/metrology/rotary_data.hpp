// Angle-sampled displacement data of an ISO 230-7 error-motion test read from CSV: columns rev,
// angle_deg and at least one channel of x_um, y_um, x2_um, y2_um, z_um, face_um (µm, positive when
// the artefact moves away from the sensor); whole revolutions sampled at the same angles, the rows
// of a revolution contiguous; an optional column direction (CW or CCW, also + / −) gives each
// revolution's sense of rotation. Format: docs/metrology.md "Rotary error motion".
#pragma once

#include <map>
#include <string>
#include <vector>

#include "volcomp/metrology/error_motion.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

/// Channel column names in the order above.
const std::vector<std::string>& RotaryChannelNames();

enum class RotationSense { kUnstated, kCw, kCcw };
const char* RotationSenseName(RotationSense sense);  // "unstated", "CW", "CCW"

struct RotaryRecord {
  std::string source;
  std::vector<double> angle_deg;                // the N angles of a revolution
  std::vector<long long> revs;                  // revolution labels in file order
  std::map<std::string, Revolutions> channels;  // channel name -> u[k][j], µm
  bool equally_spaced = true;                   // angles equally spaced over the full turn
  std::vector<RotationSense> rev_sense;         // per revolution (kUnstated without the column)
};

/// The revolutions of `record` turned in `sense`, nothing else changed.
RotaryRecord RevolutionsTurning(const RotaryRecord& record, RotationSense sense);

/// A failure (kInputInvalid) naming the line for: missing rev/angle_deg column, no channel
/// column, bad numbers, angles out of [0, 360) or not increasing, a revolution split in two parts,
/// a revolution whose angles differ from the first one's, fewer than 4 angles per revolution,
/// a direction that is not CW/CCW/+/− or that changes within a revolution.
Expected<RotaryRecord> ReadRotaryCsv(const tools::CsvTable& table);

}  // namespace volcomp::metrology
