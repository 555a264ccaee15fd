// Positioning test programs: target positions per GOST 27843-88 §2.7 and the move sequences of
// the linear cycle (fig. 1) and the pseudo-pilgrim cycle with step return (fig. 2), emitted as a
// simple G-code program. The same cycle generator serves the ISO 230-6 diagonal tests, where the
// "axis" is the distance along the diagonal. An impossible plan is a failure (kInvalidArgument,
// its message names the problem), not an exception.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/direction.hpp"

namespace volcomp::metrology {

struct TargetPlan {
  double start = 0.0;  // first end of the measured travel, mm or degrees
  double end = 0.0;    // other end (> start)
  int count = 11;      // number of target positions m (≥ 2)
  double pitch = 0.0;  // P: the largest repeating step of the axis (lead-screw pitch, encoder
                       // period, worm pitch angle ...); must be > 0
  std::uint32_t seed = 1;
  int fraction_digits = 2;  // r is a decimal fraction with this many digits (1..4)
  bool rotary = false;      // full-turn rotary axis: 0°, 90°, 180°, 270° are always included
                            // (§2.8) and targets are taken in [start, start + 360)
};

/// Target positions P_j = start + (N_j + r_j)·P (GOST 27843-88 §2.7): N_j integers spread evenly
/// over the travel, r_j random decimal fractions in [0, 1), different for every position, drawn
/// from a generator seeded with `seed` (same seed, same plan). Results are ascending, within
/// [start, end], rounded to 0.001. For `rotary`, the four cardinal angles replace the nearest
/// planned targets. A failure for an impossible plan (count < 2, pitch ≤ 0, end ≤ start, or more
/// positions than the travel holds pitches).
Expected<std::vector<double>> PlanGostTargets(const TargetPlan& plan);

enum class Cycle {
  kLinear,  // GOST fig. 1 / ISO 230-2 standard cycle: all targets ↑, then all ↓
  kPseudoPilgrim,  // GOST fig. 2 "with step return": P1↑ P2↑ P1↓ P3↑ P2↓ ... Pm↑ Pm−1↓ Pm↓
};

/// One stop of the test cycle.
struct CycleMove {
  double position = 0.0;                // along the axis (or along the diagonal)
  bool measure = false;                 // false: overrun / reversal point, no reading
  Direction approach = Direction::kUp;  // direction of travel arriving here
  int run = 0;                          // 1-based
  int target = 0;                       // 1-based target number j (0 for overrun points)
};

/// The stops of `runs` repetitions of the cycle. Every target is approached once ↑ and once ↓
/// per run; `overrun` (> 0) is the travel beyond the end targets used to reverse so that the
/// first and last targets are approached in the stated direction. A failure for fewer than 2
/// targets, runs < 1 or overrun ≤ 0.
Expected<std::vector<CycleMove>> BuildCycle(const std::vector<double>& targets,
                                            Cycle cycle,
                                            int runs,
                                            double overrun);

struct GcodeOptions {
  std::string title;                   // first comment line
  std::vector<std::string> axes{"X"};  // axis words
  std::vector<double> origin{0.0};     // coordinates at position 0 (one per axis)
  std::vector<double> direction{1.0};  // coordinates per unit of position (one per axis)
  double feed = 1000.0;                // mm/min (or deg/min)
  double dwell_s = 2.0;                // pause at each measured stop
  int decimals = 3;
  bool inch = false;  // G20: coordinates / 25.4 with decimals + 2 digits (0.00001 in = 0.254 µm),
                      // feed / 25.4 in in/min (3 decimals); positions, origin, feed stay in mm
};

/// A simple program: G21 (G20 with `inch`) G90 G94, a G0 to the first stop, G1 moves with F, G4
/// P<seconds> dwells at the measured stops with a comment naming target, direction and run, and M2
/// at the end. Axis coordinates are origin + position·direction (a failure unless axes, origin and
/// direction have one entry per axis).
Expected<std::string> EmitGcode(const std::vector<CycleMove>& moves, const GcodeOptions& options);

}  // namespace volcomp::metrology
