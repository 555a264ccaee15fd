// ISO 230-6 diagonal displacement tests: diagonal names, target positions along a diagonal (§5.2),
// and E_i, B_i per diagonal and E_d, B_d per body or face group, each diagonal evaluated like an
// ISO 230-2 axis whose coordinate is the distance from its start (mm; deviations in µm).
// Definitions: docs/metrology.md "ISO 230-6 diagonal tests".
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

/// A diagonal named by its start corner (§3.2 note 2, §3.3 note 2).
/// Accepted forms: body "+X+Y-Z" or "PPN"; face "+X-Y", "+X-Y Z300", "NP" or "NP300" (the N/P
/// form of a face diagonal means the XY plane; other planes use the signed-axis form, e.g.
/// "+X-Z Y150" or "-Y+Z").
struct DiagonalName {
  std::string text;            // normalized: "+X+Y-Z", "+X-Y Z300"
  bool body = true;            // body diagonal (3 axes) or face diagonal (2 axes)
  std::string plane;           // "XY", "XZ" or "YZ" for a face diagonal; empty for a body one
  std::string offset;          // fixed coordinate of a face diagonal, e.g. "Z300"; may be empty
  std::array<int, 3> signs{};  // start corner: +1, -1, or 0 (axis not involved), for X, Y, Z
};

/// Parses a diagonal name; nullopt when it is not one of the accepted forms.
std::optional<DiagonalName> ParseDiagonalName(const std::string& text);

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;  // mm
};

/// The name of the diagonal from P1 to P2: its start corner, i.e. per axis '+' when P1 lies at
/// the positive end (P1 > P2), '-' at the negative end; an axis with P1 = P2 is not involved and
/// gives a face diagonal with its fixed coordinate ("+X-Y Z300"). nullopt when fewer than two
/// axes move (not a diagonal).
std::optional<DiagonalName> DiagonalNameFor(const Vec3& p1, const Vec3& p2);

/// Whether `given` names the diagonal from P1 to P2: same start corner (and plane), and the same
/// fixed coordinate when `given` states one. On mismatch returns a message saying why.
std::optional<std::string> DiagonalNameMismatch(const DiagonalName& given,
                                                const Vec3& p1,
                                                const Vec3& p2);

/// A file-name-safe token: body "+X+Y-Z" -> "PPN"; face "+X-Y Z300" -> "XY_PN_Z300".
std::string DiagonalFileToken(const DiagonalName& name);

/// Target positions along the diagonal from P1 to P2 with increment I_d (§5.2).
struct DiagonalPlan {
  Vec3 p1, p2;
  double length_mm = 0.0;         // D = |P2 − P1|
  Vec3 travel_mm;                 // X_v, Y_v, Z_v = P2 − P1
  int steps = 0;                  // number of increments, round(D / I_d)
  double increment_mm = 0.0;      // effective I_d = D / steps (the rounded increment)
  Vec3 axis_increment_mm;         // I_x = (I_d/D)·X_v, I_y, I_z
  std::vector<double> distances;  // target positions along the diagonal, mm, 0..D
  std::vector<Vec3> points;       // the same as machine coordinates (P1 + t·(P2 − P1)/D)
  std::vector<std::string> warnings;
};

/// A failure (kInvalidArgument) when P1 = P2 or the increment is not positive. The increment
/// is rounded so that a whole number of steps spans the diagonal (the standard allows
/// adjusting I_d for rounding); warns when fewer than 5 targets per metre of diagonal or fewer
/// than 5 in total result (§5.2). Each point is computed from P1 directly, so no rounding
/// accumulates along the diagonal (annex A).
Expected<DiagonalPlan> PlanDiagonal(const Vec3& p1, const Vec3& p2, double increment_mm);

struct DiagonalResult {
  DiagonalName name;
  PositioningResult evaluation;  // ISO 230-2 evaluation along the diagonal
  double length_mm = 0.0;        // span of the target positions
  Span E;                        // E_i with the locations of its max and min
  Extreme B;                     // B_i = max |B_j| and where
};

struct DiagonalGroupValue {
  std::string name;    // "body" or the face plane with offset, e.g. "XY" or "XY Z300"
  double E_d = 0.0;    // max E over the group
  std::string E_from;  // diagonal giving E_d
  double B_d = 0.0;    // max B over the group
  std::string B_from;  // diagonal giving B_d
  int diagonals = 0;
  std::optional<double> E_d_U;  // U (k = 2) of E_d: that of the diagonal giving it
  std::optional<double> B_d_U;
};

struct DiagonalEvaluation {
  std::string source;
  TestConditions conditions;               // from the file's preamble
  std::vector<DiagonalResult> diagonals;   // in order of first appearance in the file
  std::optional<DiagonalGroupValue> body;  // E_d, B_d over the body diagonals
  std::vector<DiagonalGroupValue> faces;   // E_d(ab), B_d(ab) per plane (and offset)
  std::vector<std::string> warnings;
};

/// Reads the long CSV layout of positioning data with an extra `diagonal` column naming the
/// diagonal of each row (target_mm = distance from the diagonal's start), checks every
/// diagonal (both directions, ≥ min_approaches per target and direction, same targets in every
/// run, §5.2 target count) and evaluates it. A failure (kInputInvalid) naming the line for a bad
/// diagonal name or any of the checks of GroupReadings(). The reading checks of
/// reading_checks.hpp (implausible magnitude along the diagonal's length, Grubbs outliers) and
/// the preamble's test conditions go into the result.
/// With an instrument stated in `uncertainty` or the preamble, each diagonal's evaluation carries
/// its budget over the diagonal's length and E_d/B_d the U of the diagonal they come from.
Expected<DiagonalEvaluation> EvaluateDiagonals(
    const tools::CsvTable& table,
    const GroupingOptions& options,
    const PositioningUncertaintyInputs& uncertainty = {});

/// The base name of the report of `ev`: "diagonal_" and the file tokens of its diagonals, sorted
/// ("diagonal_NNN_NPN_PNN_PPN" for the four body diagonals).
std::string DiagonalReportName(const DiagonalEvaluation& ev);

}  // namespace volcomp::metrology
