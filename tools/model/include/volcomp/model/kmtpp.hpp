// КМТПП: the quasi-differential method on parametric-error tables (Pimushkin 2023, ch. 4,
// eqs. 4.1-4.11 with 2.15-2.18, algorithm of §4.2, Mathcad listing of §4.3). For a target the
// method traces a virtual motion from 0 with an astatic law, turns the axis vectors by the summed
// angular errors of the nearest table rows, and ends with one linear step from the traced point
// (smooth; the default) or from the grid node (as printed; it jumps). Only the angular columns of
// the tables are used. The variants and what they reproduce: docs/table-builders.md §5.
// Lengths in mm; table angles in µrad.
#pragma once

#include <array>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/axis_table.hpp"
#include "volcomp/model/tracker.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

/// Origin of the physical axes and their unit vectors at the origin (§4.2 steps 7-8).
struct KmtppCalibration {
  Vec3 r01_mm;
  Vec3 lx, ly, lz;
};

/// The calibration the listing uses: r01 back-extrapolated from X nodes `interval`, `interval`+1
/// (15 and 30 mm) and l_* = the interval's direction vectors (the 15→30 mm segment, digest ch.4
/// item 11). The vectors come from the model's cosine source.
KmtppCalibration KmtppCalibrationFromTracker(const TrackerModel& tracker, int interval = 1);

enum class KmtppFinalStep { kTracedPoint, kGridNode };
/// kMatrix: S += G_prev·Δq as (4.9) writes it; kListing: S_i += Δq·Q_i,prev (dot product, i.e.
/// S += G_prevᵀ·Δq) as the Mathcad listing computes it — the only form that reproduces the
/// printed R and q (digest ch.4 §5 item 5).
enum class KmtppSumForm { kMatrix, kListing };
/// Table row of a trace point: round(q/u) half away from zero (listing) or floor (eq. 2.15).
enum class KmtppIndexRule { kRound, kFloor };

struct KmtppOptions {
  double gain = 1.5;  // K, 1/(model time)
  double step = 0.1;  // l, model-time step (K·l must lie in (0, 2))
  KmtppFinalStep final_step = KmtppFinalStep::kTracedPoint;
  KmtppSumForm sum_form = KmtppSumForm::kMatrix;
  KmtppIndexRule index_rule = KmtppIndexRule::kRound;
  int max_steps = 100000;
};

/// The options that reproduce the printed Tables 4.1-4.4 and 4.9: grid-node final step, listing
/// sum, round.
KmtppOptions KmtppDissertationOptions(double gain, double step);

/// One trace point, for tests and diagnostics.
struct KmtppStep {
  Vec3 q_mm;                           // q_m after the step
  std::array<int, 3> row = {0, 0, 0};  // table rows used
  double a_rad = 0, b_rad = 0, c_rad = 0, phi_rad = 0;
  Vec3 q1, q2, q3;  // F·l_x, F·l_y, F·l_z
  Vec3 s_mm;        // accumulated displacement
};

struct KmtppResult {
  Vec3 command_mm;
  int steps = 0;    // m
  Vec3 traced_mm;   // q_m at the stop
  Vec3 reached_mm;  // R
  Mat3 g;           // G_M
  std::array<int, 3> row = {0, 0, 0};
  bool row_clamped = false;  // a trace point fell outside a table (row held at the end)
};

/// Runs the method. Tables must be equally spaced (their spacing is u): kInvalidArgument for bad
/// options or tables; kInputInvalid when the trace exceeds max_steps or the final axis-vector
/// matrix is singular.
Expected<KmtppResult> Kmtpp(const std::array<AxisErrorTable, 3>& tables,
                            const KmtppCalibration& calibration,
                            const KmtppOptions& options,
                            const Vec3& target_mm,
                            std::vector<KmtppStep>* trace = nullptr);

}  // namespace volcomp::model
