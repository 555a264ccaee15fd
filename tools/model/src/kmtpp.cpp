// КМТПП (see kmtpp.hpp).
#include "volcomp/model/kmtpp.hpp"

#include <cmath>
#include <string>

namespace volcomp::model {
namespace {

// Direction-cosine matrix (4.1) of the rotation vector θ = (A, B, C) = 2·tan(φ/2)·e, written with
// the Rodrigues–Hamilton parameters γ0 = cos(φ/2), γ = e·sin(φ/2). Since φ = 2·atan(P/2):
// γ0 = 1/sqrt(1 + P²/4) and γ_i = θ_i/2 · γ0 (defined for P = 0 too, where F = I).
Mat3 Rotation41(double a, double b, double c) {
  const double g0 = 1.0 / std::sqrt(1.0 + 0.25 * (a * a + b * b + c * c));
  const double g1 = 0.5 * a * g0, g2 = 0.5 * b * g0, g3 = 0.5 * c * g0;
  Mat3 f;
  f(0, 0) = g0 * g0 + g1 * g1 - g2 * g2 - g3 * g3;
  f(0, 1) = 2 * (g2 * g1 - g0 * g3);
  f(0, 2) = 2 * (g0 * g2 + g1 * g3);
  f(1, 0) = 2 * (g0 * g3 + g1 * g2);
  f(1, 1) = g0 * g0 + g2 * g2 - g3 * g3 - g1 * g1;
  f(1, 2) = 2 * (g3 * g2 - g0 * g1);
  f(2, 0) = 2 * (g1 * g3 - g2 * g0);
  f(2, 1) = 2 * (g1 * g0 + g2 * g3);
  f(2, 2) = g0 * g0 + g3 * g3 - g1 * g1 - g2 * g2;
  return f;
}

int Row(const AxisErrorTable& t, double q, KmtppIndexRule rule, bool* clamped) {
  const double f = (q - t.min_mm()) / t.uniform_spacing_mm();
  const double r = rule == KmtppIndexRule::kRound ? std::round(f) : std::floor(f);
  const double last = static_cast<double>(t.size() - 1);
  if (r < 0.0) {
    *clamped = true;
    return 0;
  }
  if (r > last) {
    *clamped = true;
    return static_cast<int>(last);
  }
  return static_cast<int>(r);
}

}  // namespace

KmtppCalibration KmtppCalibrationFromTracker(const TrackerModel& tracker, int interval) {
  KmtppCalibration c;
  c.r01_mm = tracker.OriginFromXInterval(interval);
  c.lx = tracker.interval_vector(0, interval);
  c.ly = tracker.interval_vector(1, interval);
  c.lz = tracker.interval_vector(2, interval);
  return c;
}

KmtppOptions KmtppDissertationOptions(double gain, double step) {
  KmtppOptions o;
  o.gain = gain;
  o.step = step;
  o.final_step = KmtppFinalStep::kGridNode;
  o.sum_form = KmtppSumForm::kListing;
  o.index_rule = KmtppIndexRule::kRound;
  return o;
}

Expected<KmtppResult> Kmtpp(const std::array<AxisErrorTable, 3>& tables,
                            const KmtppCalibration& calibration,
                            const KmtppOptions& options,
                            const Vec3& target_mm,
                            std::vector<KmtppStep>* trace) {
  const double kl = options.gain * options.step;
  if (!(kl > 0.0 && kl < 2.0)) {
    return Fail(Error::kInvalidArgument, "КМТПП: K·l must lie in (0, 2) for the trace to converge");
  }
  Vec3 u;
  for (int a = 0; a < 3; ++a) {
    const AxisErrorTable& t = tables[static_cast<std::size_t>(a)];
    if (t.size() < 2 || !(t.uniform_spacing_mm() > 0.0)) {
      return Fail(Error::kInvalidArgument,
                  std::string("КМТПП: the ") + "XYZ"[a] + " table must be equally spaced");
    }
    u[a] = t.uniform_spacing_mm();
  }

  KmtppResult out;
  Vec3 q;  // q_0 = 0
  Vec3 q_prev[3] = {calibration.lx, calibration.ly, calibration.lz};
  Vec3 q_now[3] = {calibration.lx, calibration.ly, calibration.lz};
  Vec3 s;
  int m = 0;
  bool done = false;
  while (!done) {
    if (m >= options.max_steps) return Fail(Error::kInputInvalid, "КМТПП: the trace did not stop");
    const Vec3 qdot = -options.gain * (q - target_mm);  // 9.1
    const Vec3 next = q + options.step * qdot;          // 9.2
    ++m;                                                // 9.3
    double sum[3] = {0, 0, 0};                          // 9.4-9.5: A, B, C in µrad
    for (int a = 0; a < 3; ++a) {
      const AxisErrorTable& t = tables[static_cast<std::size_t>(a)];
      const int r = Row(t, next[a], options.index_rule, &out.row_clamped);
      out.row[static_cast<std::size_t>(a)] = r;
      const Vec3& eps = t.row(static_cast<std::size_t>(r)).angular_urad;
      for (int j = 0; j < 3; ++j) sum[j] += eps[j];
    }
    const double A = 1e-6 * sum[0], B = 1e-6 * sum[1], C = 1e-6 * sum[2];
    const Mat3 f = Rotation41(A, B, C);  // 9.6-9.7
    q_now[0] = f * calibration.lx;       // 9.8
    q_now[1] = f * calibration.ly;
    q_now[2] = f * calibration.lz;
    const Vec3 dq = next - q;                          // 9.9
    if (options.sum_form == KmtppSumForm::kListing) {  // 9.10 as the listing computes it
      s += Vec3{Dot(dq, q_prev[0]), Dot(dq, q_prev[1]), Dot(dq, q_prev[2])};
    } else {  // (4.9)
      s += dq.x * q_prev[0] + dq.y * q_prev[1] + dq.z * q_prev[2];
    }
    for (int i = 0; i < 3; ++i) q_prev[i] = q_now[i];
    q = next;
    if (trace != nullptr) {
      KmtppStep st;
      st.q_mm = q;
      st.row = out.row;
      st.a_rad = A;
      st.b_rad = B;
      st.c_rad = C;
      st.phi_rad = 2.0 * std::atan(0.5 * std::sqrt(A * A + B * B + C * C));
      st.q1 = q_now[0];
      st.q2 = q_now[1];
      st.q3 = q_now[2];
      st.s_mm = s;
      trace->push_back(st);
    }
    done = std::fabs(target_mm.x - q.x) <= u.x && std::fabs(target_mm.y - q.y) <= u.y &&
           std::fabs(target_mm.z - q.z) <= u.z;  // 9.11, (4.10)
  }
  out.steps = m;
  out.traced_mm = q;
  out.reached_mm = calibration.r01_mm + s;                  // 10
  out.g = Mat3::FromColumns(q_now[0], q_now[1], q_now[2]);  // 11
  Vec3 step;
  if (!Solve(out.g, target_mm - out.reached_mm, &step)) {
    return Fail(Error::kInputInvalid, "КМТПП: singular axis-vector matrix");
  }
  Vec3 base = q;
  if (options.final_step == KmtppFinalStep::kGridNode) {
    for (int a = 0; a < 3; ++a) {
      base[a] = tables[static_cast<std::size_t>(a)].min_mm() +
                u[a] * out.row[static_cast<std::size_t>(a)];
    }
  }
  out.command_mm = base + step;  // 12, (2.18)
  return out;
}

}  // namespace volcomp::model
