// The tangential methods of chapter 2 on laser-tracker axis lines (see tracker.hpp).
#include "volcomp/model/tracker.hpp"

#include <cmath>
#include <string>

namespace volcomp::model {
namespace {

const char* AxisName(int a) { return a == 0 ? "X" : (a == 1 ? "Y" : "Z"); }

Unexpected<Failure> Invalid(const std::string& message) {
  return Fail(Error::kInvalidArgument, "tracker: " + message);
}

Expected<Vec3> SolveOrFail(const Mat3& g, const Vec3& b) {
  Vec3 x;
  if (!Solve(g, b, &x)) return Fail(Error::kInputInvalid, "tracker: singular direction matrix");
  return x;
}

}  // namespace

Outcome ValidateTrackerData(const TrackerData& data) {
  for (int a = 0; a < 3; ++a) {
    const auto& line = data.lines[static_cast<std::size_t>(a)];
    const std::string the_line = std::string("the ") + AxisName(a) + " line";
    if (line.size() < 3) return Invalid(the_line + " needs at least 3 nodes");
    if (line[0].q_mm != 0.0) {
      return Invalid(the_line + " must start at the origin (commanded 0)");
    }
    const double h = line[1].q_mm - line[0].q_mm;
    if (!(h > 0.0)) return Invalid(the_line + " must increase");
    for (std::size_t i = 0; i < line.size(); ++i) {
      const TrackerNode& n = line[i];
      if (!std::isfinite(n.q_mm) || !std::isfinite(Norm(n.p_mm))) {
        return Invalid(std::string("non-finite node on the ") + AxisName(a) + " line");
      }
      if (std::fabs(n.q_mm - h * static_cast<double>(i)) > 1e-9) {
        return Invalid(the_line + " is not equally spaced at node " + std::to_string(i));
      }
    }
  }
  return Outcome::Ok();
}

Expected<TrackerModel> TrackerModel::Create(const TrackerData& data,
                                            const TrackerOptions& options) {
  VOLCOMP_TRY(ValidateTrackerData(data));
  if (options.cosines == CosineSource::kPrinted && !data.has_printed_cosines) {
    return Invalid("printed cosines requested but the data has none");
  }
  TrackerModel m(data, options);
  for (int a = 0; a < 3; ++a) {
    const auto& line = m.data_.lines[static_cast<std::size_t>(a)];
    m.step_mm_[static_cast<std::size_t>(a)] = line[1].q_mm - line[0].q_mm;
    auto& cc = m.cc_[static_cast<std::size_t>(a)];
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Vec3 d = line[i + 1].p_mm - line[i].p_mm;
      switch (options.cosines) {
        case CosineSource::kPrinted:
          cc.push_back(line[i + 1].printed_cos);
          break;
        case CosineSource::kSigned: {
          const double len = Norm(d);
          if (!(len > 0.0)) return Invalid("two equal consecutive nodes");
          cc.push_back((1.0 / len) * d);
          break;
        }
        case CosineSource::kScaled:
          cc.push_back((1.0 / (line[i + 1].q_mm - line[i].q_mm)) * d);
          break;
      }
    }
  }
  for (int a = 0; a < 3; ++a) {
    auto& cum = m.cum_[static_cast<std::size_t>(a)];
    cum.assign(1, Vec3{});
    for (int i = 0; i < m.intervals(a); ++i) {
      cum.push_back(cum.back() + m.step_mm_[static_cast<std::size_t>(a)] * m.interval_vector(a, i));
    }
  }
  const int s = options.static_interval;
  if (s < 0 || s >= m.intervals(0) || s >= m.intervals(1) || s >= m.intervals(2)) {
    return Invalid("static interval outside the data");
  }
  m.r01_ = options.origin == OriginSource::kMeasured ? m.data_.lines[0][0].p_mm
                                                     : m.OriginFromXInterval(s);
  return m;
}

const Vec3& TrackerModel::interval_vector(int axis, int i) const {
  const auto& cc = cc_[static_cast<std::size_t>(axis)];
  if (i < 0) i = 0;
  if (i >= static_cast<int>(cc.size())) i = static_cast<int>(cc.size()) - 1;
  return cc[static_cast<std::size_t>(i)];
}

Vec3 TrackerModel::OriginFromXInterval(int i) const {
  const auto& line = data_.lines[0];
  if (i < 0) i = 0;
  if (i + 1 >= static_cast<int>(line.size())) i = static_cast<int>(line.size()) - 2;
  const TrackerNode& p1 = line[static_cast<std::size_t>(i)];
  const TrackerNode& p2 = line[static_cast<std::size_t>(i) + 1];
  const double q1t = p1.q_mm;
  if (options_.cosines == CosineSource::kScaled) {
    return p1.p_mm - (q1t / (p2.q_mm - p1.q_mm)) * (p2.p_mm - p1.p_mm);
  }
  // Eqs. (2.3)-(2.5) and the appendices' x01, y01, z01 (independent of the printed cosines).
  const double dx = p2.p_mm.x - p1.p_mm.x;
  const double ay = (p2.p_mm.y - p1.p_mm.y) / dx;
  const double az = (p2.p_mm.z - p1.p_mm.z) / dx;
  const double s = std::sqrt(1.0 + ay * ay + az * az);
  return {p1.p_mm.x - q1t / s, p1.p_mm.y - q1t * ay / s, p1.p_mm.z - q1t * az / s};
}

int TrackerModel::CellIndex(int axis, double value_mm) const {
  const double f = std::floor(value_mm / step_mm_[static_cast<std::size_t>(axis)]);
  if (!(f > 0.0)) return 0;
  const int last = intervals(axis) - 1;
  return f >= static_cast<double>(last) ? last : static_cast<int>(f);
}

Expected<TrackerStaticResult> TrackerModel::Static(const Vec3& target_mm) const {
  const int s = options_.static_interval;
  TrackerStaticResult out;
  out.r01_mm = r01_;
  out.g = Mat3::FromColumns(interval_vector(0, s), interval_vector(1, s), interval_vector(2, s));
  VOLCOMP_TRY_ASSIGN(out.command_mm, SolveOrFail(out.g, target_mm - out.r01_mm));  // (2.11)
  return out;
}

Expected<TrackerIntervalResult> TrackerModel::Interval(const Vec3& target_mm) const {
  TrackerIntervalResult out;
  for (int a = 0; a < 3; ++a) out.n[static_cast<std::size_t>(a)] = CellIndex(a, target_mm[a]);
  out.r01_mm = OriginFromXInterval(out.n[0]);
  out.g = Mat3::FromColumns(interval_vector(0, out.n[0]), interval_vector(1, out.n[1]),
                            interval_vector(2, out.n[2]));
  VOLCOMP_TRY_ASSIGN(out.command_mm, SolveOrFail(out.g, target_mm - out.r01_mm));
  return out;
}

Expected<TrackerQuasiResult> TrackerModel::QuasiDifferential(const Vec3& target_mm) const {
  TrackerQuasiResult out;
  out.r_mm = r01_;
  for (int a = 0; a < 3; ++a) {
    const int n = CellIndex(a, target_mm[a]);
    out.n[static_cast<std::size_t>(a)] = n;
    out.r_mm += cum_[static_cast<std::size_t>(a)][static_cast<std::size_t>(n)];
  }
  out.g = Mat3::FromColumns(interval_vector(0, out.n[0]), interval_vector(1, out.n[1]),
                            interval_vector(2, out.n[2]));
  VOLCOMP_TRY_ASSIGN(out.gamma_mm, SolveOrFail(out.g, target_mm - out.r_mm));
  for (int a = 0; a < 3; ++a) {
    out.command_mm[a] = step_mm_[static_cast<std::size_t>(a)] * out.n[static_cast<std::size_t>(a)] +
                        out.gamma_mm[a];
  }
  return out;
}

Vec3 TrackerModel::Position_mm(const Vec3& command_mm) const {
  Vec3 r = r01_;
  for (int a = 0; a < 3; ++a) {
    const double u = step_mm_[static_cast<std::size_t>(a)];
    const int m = CellIndex(a, command_mm[a]);
    r += cum_[static_cast<std::size_t>(a)][static_cast<std::size_t>(m)] +
         (command_mm[a] - u * m) * interval_vector(a, m);
  }
  return r;
}

Vec3 TrackerModel::StaticPosition_mm(const Vec3& command_mm) const {
  const int s = options_.static_interval;
  return r01_ + command_mm.x * interval_vector(0, s) + command_mm.y * interval_vector(1, s) +
         command_mm.z * interval_vector(2, s);
}

InverseSolution TrackerModel::ExactInverse(const Vec3& target_mm, double tolerance_mm) const {
  const auto error_mm = [this](const Vec3& q) { return Position_mm(q) - q; };
  return InvertError(error_mm, target_mm, tolerance_mm);
}

}  // namespace volcomp::model
