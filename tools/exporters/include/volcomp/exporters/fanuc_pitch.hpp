// FANUC pitch error compensation (0i / 16i / 18i / 30i) as an entry sheet, from error tables
// (error_table.hpp): the per-axis parameters 3620 (reference point number), 3621/3622 (most
// negative / positive point number), 3623 (magnification), 3624 (point interval) and, for a
// two-direction test, 3605#0 = 1 with 3626 (most negative point of the negative-direction
// block) and 3627 (the compensation at the reference position approached from the negative
// side, the reference return assumed to approach moving positive), then one increment per point.
// Not a punch file: the block syntax of pitch data in a parameter file is not confirmed by
// volcomp's sources, so the sheet is for entry on the control's screens and says so.
// Points: the grid node x_i (equally spaced, the reference position one of them) ends the interval
// (x_{i−1}, x_i] whose point number is 3620 + (i − r), r the reference's node; the value of a
// point is output while moving through its interval (a staircase; 0i parameter manual).
// Units: the machine's (FanucOptions::unit): on an inch machine positions, 3624 and the detection
// unit are in inches (3624's unit is the machine unit, its least step the increment system's).
// Values: corrections (C) = −(actual − nominal), in counts of detection unit × 3623, the running
// sum (0 at the reference) rounded to whole counts and differenced per point, so rounding does
// not accumulate. Sign: Fanuc enters the compensation amount (0i parameter manual plots it as the
// running sum of the increments); Fanuc's own wording of the sign is not in volcomp's sources
// (secondary: cnc.wiki; Mitsubishi's analogue is (interval − actual movement), i.e. C): --negate.
// Limits: increments −128..127 per point (FOCAS IODBPI carries them as signed char; the range is
// inferred), data numbers 0..1023 shared by all axes (inferred), equal spacing, linear axes
// (rotary axes need 3625 and a zero sum per revolution: not written).
// Sources: 0i-PB parameter manual p. 108; A-77810E (bidirectional); 15i parameter manual p. 32;
// strangesast/fwlib fwlib32.h (IODBPI); cnc.wiki (shared reference §B4).
#pragma once

#include <string>
#include <vector>

#include "volcomp/exporters/error_table.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

inline constexpr int kFanucMinIncrement = -128;
inline constexpr int kFanucMaxIncrement = 127;
inline constexpr int kFanucMaxPointNumber = 1023;

struct FanucOptions {
  LengthUnit unit = LengthUnit::kMm;  // the machine's: of every table, 3624 and the sheet
  double detection_unit = 0.001;      // the axis's detection unit in `unit` (IS-B: 0.001 mm,
                                      // 0.0001 in)
  int magnification = 1;              // parameter 3623, ≥ 1
};

struct FanucAxis {
  char axis = 'X';
  std::string source;  // the test file, named on the sheet
  ErrorTable table;    // zero_at: the reference position, a grid node (required)
};

struct FanucPoint {
  int number = 0;
  double from = 0, to = 0;  // the interval, machine units
  int increment = 0;        // counts
  int total = 0;            // the running sum: the correction at `to`, counts
};

struct FanucAxisSheet {
  char axis = 'X';
  int reference_point = 0;  // 3620
  int most_negative = 0;    // 3621
  int most_positive = 0;    // 3622
  double interval = 0;      // 3624, machine units
  std::vector<FanucPoint> forward;
  bool bidirectional = false;
  int negative_block = 0;      // 3626
  int reference_opposite = 0;  // 3627, counts
  std::vector<FanucPoint> reverse;
};

struct FanucSheet {
  std::string text;
  std::vector<FanucAxisSheet> axes;
  int last_point = 0;  // the highest data number used
};

/// The axes take consecutive blocks of data numbers from 0 in the order given.
/// kInvalidArgument naming the axis, the value, the limit and the fix: a rotary axis, unequal
/// spacing, no reference or one that is not a grid node, an increment outside −128..127, a data
/// number past 1023, a detection unit ≤ 0 or magnification < 1.
Expected<FanucSheet> BuildFanucSheet(const std::vector<FanucAxis>& axes,
                                     const FanucOptions& options);

}  // namespace volcomp::exporters
