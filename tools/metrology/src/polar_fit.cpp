// LSC and minimum-zone centres of polar profiles.
#include "volcomp/metrology/polar_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "volcomp/tools/math_constants.hpp"

namespace volcomp::metrology {
namespace {

using tools::kPi;

double Rad(double deg) { return deg * kPi / 180.0; }

std::size_t DistinctAngles(const std::vector<double>& angle_deg) {
  std::set<long long> s;
  for (double a : angle_deg) {
    double m = std::fmod(a, 360.0);
    if (m < 0) m += 360.0;
    s.insert(std::llround(m * 1e6) % 360000000LL);
  }
  return s.size();
}

// Solves the n×n system M·x = v by Gaussian elimination with partial pivoting; false if singular.
bool Solve(std::vector<std::vector<double>> M, std::vector<double> v, std::vector<double>* x) {
  const std::size_t n = v.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < n; ++r) {
      if (std::fabs(M[r][c]) > std::fabs(M[piv][c])) piv = r;
    }
    if (std::fabs(M[piv][c]) < 1e-14) return false;
    std::swap(M[c], M[piv]);
    std::swap(v[c], v[piv]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      const double f = M[r][c] / M[c][c];
      for (std::size_t k = c; k < n; ++k) M[r][k] -= f * M[c][k];
      v[r] -= f * v[c];
    }
  }
  x->assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) (*x)[i] = v[i] / M[i][i];
  return true;
}

// Dense two-phase simplex for: maximize cᵀw subject to A·w = b (b ≥ 0), w ≥ 0, with Bland's
// rule (no cycling). Returns the dual prices y (the solution of Bᵀy = c_B at the optimum).
Expected<std::vector<double>> SimplexDualPrices(const std::vector<std::vector<double>>& A,
                                                const std::vector<double>& b,
                                                const std::vector<double>& c) {
  const std::size_t m = A.size(), n = c.size(), cols = n + m;
  const double eps = 1e-11;
  std::vector<std::vector<double>> T(m, std::vector<double>(cols + 1, 0.0));
  std::vector<std::size_t> basis(m);
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < n; ++j) T[i][j] = A[i][j];
    T[i][n + i] = 1.0;
    T[i][cols] = b[i];
    basis[i] = n + i;
  }
  std::vector<double> d(cols + 1, 0.0);
  auto pivot = [&](std::size_t r, std::size_t e) {
    const double p = T[r][e];
    for (double& v : T[r]) v /= p;
    for (std::size_t i = 0; i < m; ++i) {
      if (i == r || T[i][e] == 0.0) continue;
      const double f = T[i][e];
      for (std::size_t k = 0; k <= cols; ++k) T[i][k] -= f * T[r][k];
    }
    const double f = d[e];
    for (std::size_t k = 0; k <= cols; ++k) d[k] -= f * T[r][k];
    basis[r] = e;
  };
  // Reduced costs d_j = c_j − c_Bᵀ B⁻¹ A_j for the cost vector `cost` (size cols).
  auto reduced = [&](const std::vector<double>& cost) {
    for (std::size_t j = 0; j <= cols; ++j) {
      double s = j < cols ? cost[j] : 0.0;
      for (std::size_t i = 0; i < m; ++i) s -= cost[basis[i]] * T[i][j];
      d[j] = s;
    }
  };
  auto run = [&](std::size_t allowed) -> Outcome {
    for (int iter = 0; iter < 100000; ++iter) {
      std::size_t e = cols;
      for (std::size_t j = 0; j < allowed; ++j) {
        if (d[j] > eps) {
          e = j;
          break;
        }
      }
      if (e == cols) return Outcome::Ok();
      std::size_t r = m;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < m; ++i) {
        if (T[i][e] > eps) {
          const double ratio = T[i][cols] / T[i][e];
          if (r == m || ratio < best - 1e-15 ||
              (std::fabs(ratio - best) <= 1e-15 && basis[i] < basis[r])) {
            best = ratio;
            r = i;
          }
        }
      }
      if (r == m) return Fail(Error::kInvalidArgument, "centre fit: unbounded linear program");
      pivot(r, e);
    }
    return Fail(Error::kInvalidArgument, "centre fit: simplex did not converge");
  };
  // Phase 1: maximize −Σ artificials.
  std::vector<double> cost1(cols, 0.0);
  for (std::size_t i = 0; i < m; ++i) cost1[n + i] = -1.0;
  reduced(cost1);
  VOLCOMP_TRY(run(cols));
  // A positive artificial left at the optimum of phase 1: no w satisfies A·w = b (for the
  // one-sided centres, all angles lie within a half circle).
  for (std::size_t i = 0; i < m; ++i) {
    if (basis[i] >= n && T[i][cols] > 1e-9) {
      return Fail(Error::kInvalidArgument, "centre fit: infeasible linear program");
    }
  }
  // Drive remaining artificials out of the basis (they are at zero level).
  for (std::size_t i = 0; i < m; ++i) {
    if (basis[i] < n) continue;
    for (std::size_t j = 0; j < n; ++j) {
      if (std::fabs(T[i][j]) > 1e-9) {
        pivot(i, j);
        break;
      }
    }
  }
  // Phase 2 with the real costs; artificials never re-enter.
  std::vector<double> cost2(cols, 0.0);
  for (std::size_t j = 0; j < n; ++j) cost2[j] = c[j];
  reduced(cost2);
  VOLCOMP_TRY(run(n));
  reduced(cost2);
  // For an artificial column e_i with zero cost, d = −y_i.
  std::vector<double> y(m);
  for (std::size_t i = 0; i < m; ++i) y[i] = -d[n + i];
  return y;
}

// The one-sided centres on a profile q scaled to O(1) (q_j with angles c_j = cos θ_j,
// s_j = sin θ_j): stage 1 is min u over (u, a, b) with u + a·c_j + b·s_j ≥ q_j (the MCC); stage
// 2, among those centres, maximizes the inner bound l ≤ q_j − a·c_j − b·s_j (a tie-break that
// only matters where stage 1 leaves a segment of centres). Both as dual prices of the simplex
// above: min bᵀy s.t. Aᵀy ≥ cost has prices y. Returns {u, a, b}.
Expected<CentreFit> CircumscribedOfScaled(const std::vector<double>& angle_deg,
                                          const std::vector<double>& q) {
  const std::size_t n = q.size();
  std::vector<double> cs(n), sn(n);
  for (std::size_t j = 0; j < n; ++j) {
    cs[j] = std::cos(Rad(angle_deg[j]));
    sn[j] = std::sin(Rad(angle_deg[j]));
  }
  std::vector<std::vector<double>> A(3, std::vector<double>(n, 0.0));
  for (std::size_t j = 0; j < n; ++j) A[0][j] = 1.0, A[1][j] = cs[j], A[2][j] = sn[j];
  VOLCOMP_TRY_ASSIGN(const std::vector<double> y1, SimplexDualPrices(A, {1.0, 0.0, 0.0}, q));
  const double u = y1[0] + 1e-12;  // round-off room for stage 2's feasibility
  // Stage 2: y = (−l, a, b), min −l; lower rows (1, −c_j, −s_j)·y ≥ −q_j, upper rows
  // (0, c_j, s_j)·y ≥ q_j − u.
  std::vector<std::vector<double>> A2(3, std::vector<double>(2 * n, 0.0));
  std::vector<double> cost2(2 * n);
  for (std::size_t j = 0; j < n; ++j) {
    A2[0][j] = 1.0, A2[1][j] = -cs[j], A2[2][j] = -sn[j];
    A2[1][n + j] = cs[j], A2[2][n + j] = sn[j];
    cost2[j] = -q[j];
    cost2[n + j] = q[j] - u;
  }
  VOLCOMP_TRY_ASSIGN(const std::vector<double> y2, SimplexDualPrices(A2, {1.0, 0.0, 0.0}, cost2));
  return CentreFit{y1[0], y2[1], y2[2]};
}

enum class Side { kCircumscribed, kInscribed };

// MCC directly; MIC as the MCC of −p (max_c min_j r_j(p) = −min_c max_j r_j(−p), centre negated).
Expected<CentreFit> OneSidedCentre(const std::vector<double>& angle_deg,
                                   const std::vector<double>& p,
                                   Side side,
                                   const char* what) {
  if (angle_deg.size() != p.size() || DistinctAngles(angle_deg) < 4) {
    return Fail(Error::kInvalidArgument, std::string(what) + " needs at least 4 distinct angles");
  }
  VOLCOMP_TRY_ASSIGN(const CentreFit lsc, FitLeastSquaresCentre(angle_deg, p));
  const double sign = side == Side::kCircumscribed ? 1.0 : -1.0;
  double scale = 0.0;
  for (double v : p) scale = std::max(scale, std::fabs(v - lsc.mean));
  if (!(scale > 0.0)) return lsc;
  std::vector<double> q(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) q[j] = sign * (p[j] - lsc.mean) / scale;
  const auto c = CircumscribedOfScaled(angle_deg, q);
  if (!c.ok()) {
    return Fail(Error::kInvalidArgument,
                std::string(what) +
                    ": no centre (the angles must not all lie within a half "
                    "circle: " +
                    c.error().message + ")");
  }
  return CentreFit{lsc.mean + sign * c->mean * scale, sign * c->a * scale, sign * c->b * scale};
}

}  // namespace

Expected<CentreFit> FitMinimumCircumscribedCentre(const std::vector<double>& angle_deg,
                                                  const std::vector<double>& p) {
  return OneSidedCentre(angle_deg, p, Side::kCircumscribed, "minimum circumscribed centre");
}

Expected<CentreFit> FitMaximumInscribedCentre(const std::vector<double>& angle_deg,
                                              const std::vector<double>& p) {
  return OneSidedCentre(angle_deg, p, Side::kInscribed, "maximum inscribed centre");
}

Expected<CentreFit> FitLeastSquaresCentre(const std::vector<double>& angle_deg,
                                          const std::vector<double>& p) {
  if (angle_deg.size() != p.size() || DistinctAngles(angle_deg) < 3) {
    return Fail(Error::kInvalidArgument, "least-squares centre needs at least 3 distinct angles");
  }
  std::vector<std::vector<double>> M(3, std::vector<double>(3, 0.0));
  std::vector<double> v(3, 0.0);
  for (std::size_t j = 0; j < p.size(); ++j) {
    const double f[3] = {1.0, std::cos(Rad(angle_deg[j])), std::sin(Rad(angle_deg[j]))};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) M[r][c] += f[r] * f[c];
      v[r] += f[r] * p[j];
    }
  }
  std::vector<double> x;
  if (!Solve(M, v, &x)) {
    return Fail(Error::kInvalidArgument, "least-squares centre: singular angles");
  }
  return CentreFit{x[0], x[1], x[2]};
}

Expected<CentreFit> FitMinimumZoneCentre(const std::vector<double>& angle_deg,
                                         const std::vector<double>& p) {
  if (angle_deg.size() != p.size() || DistinctAngles(angle_deg) < 4) {
    return Fail(Error::kInvalidArgument, "minimum-zone centre needs at least 4 distinct angles");
  }
  // Scale to O(1) for the simplex tolerances.
  VOLCOMP_TRY_ASSIGN(const CentreFit lsc, FitLeastSquaresCentre(angle_deg, p));
  double scale = 0.0;
  for (double v : p) scale = std::max(scale, std::fabs(v - lsc.mean));
  if (!(scale > 0.0)) return lsc;
  const std::size_t n = p.size();
  // Dual of the Chebyshev fit: w = (λ_1..λ_n, μ_1..μ_n) ≥ 0,
  //   Σ(λ−μ) = 0, Σ(λ−μ)cos θ = 0, Σ(λ−μ)sin θ = 0, Σ(λ+μ) = 1, maximize Σ q(λ−μ),
  // whose dual prices are (m, a, b, t) of the primal min t s.t. |q − m − a cos − b sin| ≤ t.
  std::vector<std::vector<double>> A(4, std::vector<double>(2 * n, 0.0));
  std::vector<double> c(2 * n);
  for (std::size_t j = 0; j < n; ++j) {
    const double q = (p[j] - lsc.mean) / scale;
    const double cs = std::cos(Rad(angle_deg[j])), sn = std::sin(Rad(angle_deg[j]));
    A[0][j] = 1.0, A[0][n + j] = -1.0;
    A[1][j] = cs, A[1][n + j] = -cs;
    A[2][j] = sn, A[2][n + j] = -sn;
    A[3][j] = 1.0, A[3][n + j] = 1.0;
    c[j] = q;
    c[n + j] = -q;
  }
  VOLCOMP_TRY_ASSIGN(const std::vector<double> y, SimplexDualPrices(A, {0.0, 0.0, 0.0, 1.0}, c));
  CentreFit mz{lsc.mean + y[0] * scale, y[1] * scale, y[2] * scale};
  // Never report a zone wider than the LSC one (guards against round-off in the simplex).
  if (ValueAbout(angle_deg, p, mz.a, mz.b) > ValueAbout(angle_deg, p, lsc.a, lsc.b)) return lsc;
  return mz;
}

std::vector<double> ResidualsAbout(const std::vector<double>& angle_deg,
                                   const std::vector<double>& p,
                                   double a,
                                   double b) {
  std::vector<double> r(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) {
    r[j] = p[j] - a * std::cos(Rad(angle_deg[j])) - b * std::sin(Rad(angle_deg[j]));
  }
  return r;
}

double ValueAbout(const std::vector<double>& angle_deg,
                  const std::vector<double>& p,
                  double a,
                  double b) {
  const auto r = ResidualsAbout(angle_deg, p, a, b);
  if (r.empty()) return 0.0;
  const auto mm = std::minmax_element(r.begin(), r.end());
  return *mm.second - *mm.first;
}

}  // namespace volcomp::metrology
