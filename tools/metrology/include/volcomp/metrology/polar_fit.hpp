// Centres of an error-motion polar profile (ISO 230-7 §3.7), in the linearized (limaçon) form
// that is valid when the error motion is small against the base circle r0 and independent of r0:
// the profile p(θ_j) is compared with m + a·cos θ_j + b·sin θ_j, and (a, b) is the offset of
// the centre from the PC centre (the polar chart origin). Removing a·cos θ + b·sin θ is removing
// the fundamental (once-per-revolution) component.
// Units: whatever the profile uses (µm, or µrad for tilt); angles in degrees. Fits that cannot be
// made are failures (kInvalidArgument), not exceptions.
#pragma once

#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::metrology {

struct CentreFit {
  double mean = 0.0;  // m
  double a = 0.0;     // centre offset along the 0° direction (X)
  double b = 0.0;     // centre offset along the 90° direction (Y)
};

/// Least-squares circle centre (LSC, §3.7.4): minimizes Σ (p_j − m − a·cos θ_j − b·sin θ_j)².
/// Solves the 3×3 normal equations, so unequal angle spacing is handled; for equal spacing over
/// whole revolutions this is m = mean, a = (2/N)Σp·cos θ, b = (2/N)Σp·sin θ.
/// Needs at least 3 distinct angles.
Expected<CentreFit> FitLeastSquaresCentre(const std::vector<double>& angle_deg,
                                          const std::vector<double>& p);

/// Minimum radial separation centre (MRS, the minimum zone, §3.7.5): minimizes the width of
/// the zone between two concentric circles containing the profile, i.e. the Chebyshev fit
/// min over (m, a, b) of max_j |p_j − m − a·cos θ_j − b·sin θ_j|, solved exactly as a linear
/// program (simplex on the dual, 4 rows). Needs at least 4 distinct angles.
Expected<CentreFit> FitMinimumZoneCentre(const std::vector<double>& angle_deg,
                                         const std::vector<double>& p);

/// Minimum circumscribed circle centre (MCC, §3.7.7): minimizes the outer radius
/// u = max_j (p_j − a·cos θ_j − b·sin θ_j), the smallest circle about the centre that contains the
/// profile. Where several centres give the same smallest circle (a profile touching it at only
/// two opposite angles), the one with the largest inner radius, i.e. the smallest value, is taken.
/// The returned mean is u. Needs at least 4 distinct angles that do not all lie within a half
/// circle (otherwise the circle can shrink without bound: kInvalidArgument).
Expected<CentreFit> FitMinimumCircumscribedCentre(const std::vector<double>& angle_deg,
                                                  const std::vector<double>& p);

/// Maximum inscribed circle centre (MIC, §3.7.6): maximizes the inner radius
/// l = min_j (p_j − a·cos θ_j − b·sin θ_j), the largest circle about the centre inside the profile;
/// ties broken by the smallest outer radius. The returned mean is l. Same needs as the MCC.
Expected<CentreFit> FitMaximumInscribedCentre(const std::vector<double>& angle_deg,
                                              const std::vector<double>& p);

/// Radial deviations of p about the centre (a, b): p_j − a·cos θ_j − b·sin θ_j.
std::vector<double> ResidualsAbout(const std::vector<double>& angle_deg,
                                   const std::vector<double>& p,
                                   double a,
                                   double b);

/// Error-motion value about a centre: max − min of ResidualsAbout() (two concentric circles
/// about the centre that just contain the profile).
double ValueAbout(const std::vector<double>& angle_deg,
                  const std::vector<double>& p,
                  double a,
                  double b);

}  // namespace volcomp::metrology
