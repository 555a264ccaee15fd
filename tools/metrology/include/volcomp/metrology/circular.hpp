// ISO 230-4 circular test: the evaluation of a contour run in both directions (clockwise and
// counter-clockwise) around a nominal circle, from the radial deviation of the actual path
// measured at angles (a ballbar's readings). Definitions of ISO 230-4:2005, clause 3:
//   G    circular deviation of one path: the radial separation of the two concentric circles
//        about that path's least-squares centre that just enclose it;
//   G(b) bidirectional circular deviation: the same for both paths about one least-squares centre;
//   H    circular hysteresis: the largest radial difference between the CW and CCW paths at the
//        same angle, both about that common centre;
//   F    radial deviation: the actual path against the nominal circle (nominal centre, nominal
//        radius), its largest (F max) and smallest (F min) value.
// The least-squares centre is fitted in the linearized (limaçon) form of polar_fit.hpp, exact to
// e²/(2R) for a centre offset e from the nominal centre on a circle of radius R (below 0.001 µm
// for e = 10 µm on R = 50 mm). Where the two paths are read at different angles, H compares each
// reading with the other path linearly interpolated between its two neighbouring readings
// (periodic in angle). Angles in degrees, counter-clockwise from the plane's first axis as seen
// from the plane's positive normal, any value (taken modulo 360); deviations in µm, positive
// outward. Bad data are Failures (kInputInvalid) naming the file and line, never exceptions.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

/// One contouring direction's readings.
struct CircularPath {
  std::vector<double> angle_deg;
  std::vector<double> deviation_um;  // actual radius − nominal radius
};

struct CircularData {
  CircularPath cw;
  CircularPath ccw;
  std::string source;              // names the data in messages ("" for none)
  double nominal_radius_mm = 0.0;  // 0 when the file gives deviations
};

struct CircularResult {
  bool has_cw = false, has_ccw = false;
  std::size_t points_cw = 0, points_ccw = 0;
  double G_cw_um = 0, G_ccw_um = 0;   // per direction, about its own least-squares centre
  double G_b_um = 0;                  // both directions, one least-squares centre (needs both)
  double H_um = 0;                    // circular hysteresis (needs both)
  double H_angle_deg = 0;             // where H occurs
  double F_max_um = 0, F_min_um = 0;  // about the nominal centre and radius, every reading
  double centre_offset_x_um = 0, centre_offset_y_um = 0;  // least-squares centre of all readings
                                                          // from the nominal centre
  double mean_radius_dev_um = 0;      // the least-squares circle's radius − nominal radius
  std::vector<std::string> warnings;  // e.g. a path with a wide gap between readings
};

/// The evaluation; each path given needs readings at 3 or more distinct angles. A path missing
/// from the data leaves has_cw / has_ccw false and G(b), H unset (false has_* of both: failure).
Expected<CircularResult> EvaluateCircular(const CircularData& data);

/// Reads `direction,angle_deg,deviation_um` (direction cw|ccw, any case), or radius_mm in place
/// of deviation_um when `nominal_radius_mm` > 0 (the deviation is then radius − nominal). A file
/// with radius_mm but no deviation_um and no radius is refused with a hint. Failures name the
/// file and line.
Expected<CircularData> ReadCircularCsv(const tools::CsvTable& csv, double nominal_radius_mm);

}  // namespace volcomp::metrology
