// The dissertation's volumetric-error formulation, reproduced with its quirks (named variant):
// Pimushkin (STANKIN, 2023), ch. 3, eqs. (3.5)-(3.10) and Appendix А, exactly as the printed
// numbers were computed. Angles act only through the tool vector r, the nine angles are summed per
// direction and scaled by k, the linear errors are grouped by the moving axis (3.8), no
// squareness. Where it departs from physics: docs/table-builders.md §3.
// Units: the dissertation's (linear µm, angles µm/mm = mrad, r in µm).
#pragma once

#include <array>

#include "volcomp/model/axis_table.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

/// The 18 parametric errors of the three axes at one point, in the dissertation's units:
/// delta_um[i][j] = linear error of axis i in direction j (µm), eps_um_per_mm[i][j] = rotation of
/// axis i's triad about direction j (µm/mm = mrad). i, j: 0 = x, 1 = y, 2 = z.
struct PointErrors {
  double delta_um[3][3];
  double eps_um_per_mm[3][3];
};

/// Which of the dissertation's results: δ (first order, 3.10), δ+ or δ− (second order, 3.9).
enum class DissertationCase { kFirstOrder, kPlus, kMinus };

struct DissertationOptions {
  double k = 1.0;                           // scale of the nine angles only
  Vec3 r_um = {10000.0, 10000.0, 10000.0};  // tool vector; every printed table uses 10 mm
  DissertationCase which = DissertationCase::kFirstOrder;
  bool group_linear_by_direction = false;  // true: δx = δ_xx+δ_yx+δ_zx (physics, NOT printed)
};

struct DissertationResult {
  Vec3 delta_um;       // volumetric error vector δ(Q, r)
  double norm_um = 0;  // ОП = ‖δ‖, the printed number
  double a_rad = 0;    // components of E″ (second-order ones for δ±)
  double b_rad = 0;
  double c_rad = 0;
  double l = 1;  // Rodrigues coefficient (1 for first order)
};

DissertationResult DissertationError(const PointErrors& errors, const DissertationOptions& options);

/// The 18 errors at a position: each axis table sampled at its own coordinate (rows at nodes,
/// linear in between). Table columns are converted from µrad to µm/mm.
PointErrors PointErrorsAt(const std::array<AxisErrorTable, 3>& axes, const Vec3& position_mm);

}  // namespace volcomp::model
