// ISO 230-7 synchronous / asynchronous / total error-motion values.
#include "volcomp/metrology/error_motion.hpp"

#include <algorithm>
#include <cmath>

#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/tools/math_constants.hpp"

namespace volcomp::metrology {
namespace {

using tools::kPi;

CentreValues About(const ErrorMotion& em, CentreKind kind, double a, double b) {
  CentreValues v;
  v.kind = kind;
  v.a = a;
  v.b = b;
  v.synchronous = ValueAbout(em.angle_deg, em.synchronous, a, b);
  v.inner = ValueAbout(em.angle_deg, em.inner, a, b);
  v.outer = ValueAbout(em.angle_deg, em.outer, a, b);
  double lo = 0.0, hi = 0.0;
  bool first = true;
  for (const auto& rev : em.total) {
    for (double r : ResidualsAbout(em.angle_deg, rev, a, b)) {
      if (first || r < lo) lo = r;
      if (first || r > hi) hi = r;
      first = false;
    }
  }
  v.total = hi - lo;
  return v;
}

}  // namespace

const char* CentreName(CentreKind kind) {
  switch (kind) {
    case CentreKind::kPc:
      return "PC";
    case CentreKind::kLsc:
      return "LSC";
    case CentreKind::kMrs:
      return "MRS";
    case CentreKind::kMic:
      return "MIC";
    case CentreKind::kMcc:
      return "MCC";
  }
  return "?";
}

Expected<ErrorMotion> AnalyseErrorMotion(const std::vector<double>& angle_deg,
                                         const Revolutions& u,
                                         const CentreSelection& centres) {
  const std::size_t n = angle_deg.size();
  if (u.empty()) return Fail(Error::kInvalidArgument, "error motion needs at least one revolution");
  if (n < 4) {
    return Fail(Error::kInvalidArgument, "error motion needs at least 4 angles per revolution");
  }
  for (const auto& rev : u) {
    if (rev.size() != n) return Fail(Error::kInvalidArgument, "revolutions of unequal length");
  }
  ErrorMotion em;
  em.angle_deg = angle_deg;
  em.total = u;
  em.revolutions = static_cast<int>(u.size());
  em.synchronous.assign(n, 0.0);
  em.inner.assign(n, 0.0);
  em.outer.assign(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    double sum = 0.0, lo = u[0][j], hi = u[0][j];
    for (const auto& rev : u) {
      sum += rev[j];
      lo = std::min(lo, rev[j]);
      hi = std::max(hi, rev[j]);
    }
    em.synchronous[j] = sum / static_cast<double>(u.size());
    em.inner[j] = lo;
    em.outer[j] = hi;
    if (j == 0 || hi - lo > em.asynchronous_value) {
      em.asynchronous_value = hi - lo;
      em.asynchronous_angle_deg = angle_deg[j];
    }
  }
  VOLCOMP_TRY_ASSIGN(const CentreFit lsc, FitLeastSquaresCentre(angle_deg, em.synchronous));
  em.lsc_mean = lsc.mean;
  em.pc = About(em, CentreKind::kPc, 0.0, 0.0);
  em.lsc = About(em, CentreKind::kLsc, lsc.a, lsc.b);
  if (centres.mrs) {
    VOLCOMP_TRY_ASSIGN(const CentreFit c, FitMinimumZoneCentre(angle_deg, em.synchronous));
    em.mrs = About(em, CentreKind::kMrs, c.a, c.b);
  }
  if (centres.mic) {
    VOLCOMP_TRY_ASSIGN(const CentreFit c, FitMaximumInscribedCentre(angle_deg, em.synchronous));
    em.mic = About(em, CentreKind::kMic, c.a, c.b);
  }
  if (centres.mcc) {
    VOLCOMP_TRY_ASSIGN(const CentreFit c, FitMinimumCircumscribedCentre(angle_deg, em.synchronous));
    em.mcc = About(em, CentreKind::kMcc, c.a, c.b);
  }
  em.fundamental_value = 2.0 * std::hypot(lsc.a, lsc.b);
  em.fundamental_angle_deg = std::atan2(lsc.b, lsc.a) * 180.0 / kPi;
  return em;
}

const CentreValues& ValuesAbout(const ErrorMotion& em, CentreKind kind) {
  if (kind == CentreKind::kMrs && em.mrs) return *em.mrs;
  if (kind == CentreKind::kMic && em.mic) return *em.mic;
  if (kind == CentreKind::kMcc && em.mcc) return *em.mcc;
  return kind == CentreKind::kPc ? em.pc : em.lsc;
}

std::vector<const CentreValues*> ComputedCentres(const ErrorMotion& em) {
  std::vector<const CentreValues*> c = {&em.pc, &em.lsc};
  for (const auto* o : {&em.mrs, &em.mic, &em.mcc}) {
    if (*o) c.push_back(&**o);
  }
  return c;
}

}  // namespace volcomp::metrology
