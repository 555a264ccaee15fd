// Measurement programs for the simulated CNC: G-code (what an integrator runs on a real
// controller) and the stops where the instrument reads, one dwell (G4) per stop in order and
// nowhere else; the first stop is the instrument's datum. Targets and cycles come from
// tools/metrology (PlanGostTargets, BuildCycle, PlanDiagonal); a plan it refuses (fewer than 2
// targets, no runs, a diagonal of length 0) fails with kInvalidArgument and its reason.
// Units: mm, mm/s, seconds.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/direction.hpp"
#include "volcomp/metrology/test_program.hpp"

namespace volcomp::sim {

using Point3 = std::array<double, 3>;

struct MeasuredStop {
  Point3 point_mm = {0, 0, 0};  // commanded position (machine frame)
  double along_mm = 0;          // position along the test line (the target's coordinate)
  metrology::Direction approach = metrology::Direction::kUp;
  int run = 0;         // 1-based; 0 for the datum
  int target = 0;      // 1-based target number; 0 for the datum
  bool datum = false;  // the instrument is zeroed here, no reading
};

struct TestProgram {
  std::string name;
  std::string gcode;
  std::vector<MeasuredStop> stops;  // in program order, one per G4
  Point3 origin_mm = {0, 0, 0};     // the line's point at along = 0
  Point3 direction = {1, 0, 0};     // unit vector of the line (machine frame)
};

struct CycleOptions {
  int runs = 5;
  double overrun_mm = 5;
  double feed_mm_s = 1000;  // G1 feed along the line
  double dwell_s = 0.05;
};

/// A line test: `origin` + along * `direction` for the stops of metrology::BuildCycle(targets).
Expected<TestProgram> LineTestProgram(const std::string& name,
                                      const Point3& origin_mm,
                                      const Point3& direction,
                                      const std::vector<double>& targets_mm,
                                      const CycleOptions& options);

/// GOST 27843 linear cycle along `axis` (0..2) through `line_point_mm` (the other coordinates).
Expected<TestProgram> GostAxisProgram(int axis,
                                      const Point3& line_point_mm,
                                      const std::vector<double>& targets_mm,
                                      const CycleOptions& options);

/// ISO 230-6 body diagonal from `p1` to `p2` with targets every ~`increment_mm` (§5.2).
Expected<TestProgram> DiagonalProgram(const std::string& name,
                                      const Point3& p1_mm,
                                      const Point3& p2_mm,
                                      double increment_mm,
                                      const CycleOptions& options);

/// Rapid moves to `points` (the first one is the datum) with a dwell at each. With
/// `approach_mm` > 0 every point is approached from `approach_mm` below on every axis (a rapid to
/// the point minus (a, a, a) first): unidirectional, every axis moving positive into the point.
TestProgram PointSetProgram(const std::string& name,
                            const std::vector<Point3>& points_mm,
                            double dwell_s,
                            double approach_mm = 0);

/// One run ↑ and ↓ (× `runs`) along `axis` through `reference_mm`, stopping at `positions_mm`.
Expected<TestProgram> ParametricProgram(int axis,
                                        const Point3& reference_mm,
                                        const std::vector<double>& positions_mm,
                                        const CycleOptions& options);

/// The body diagonals of the box [lo, hi] in ISO 230-6 naming by start corner:
/// "-X-Y-Z", "+X-Y-Z", "-X+Y-Z", "+X+Y-Z", each to the opposite corner.
struct BodyDiagonal {
  std::string name;
  Point3 p1, p2;
};
std::vector<BodyDiagonal> BodyDiagonals(const Point3& lo_mm, const Point3& hi_mm);

}  // namespace volcomp::sim
