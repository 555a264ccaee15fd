// The tangential methods of chapter 2 on laser-tracker axis lines (see tracker.hpp).
#include "volcomp/model/tracker.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "s500_data.hpp"

namespace volcomp::model {
namespace {

const char* AxisName(int a) { return a == 0 ? "X" : (a == 1 ? "Y" : "Z"); }

template <std::size_t N>
std::vector<TrackerNode> Line(const data::TrackerRow (&rows)[N], int axis) {
  std::vector<TrackerNode> out;
  for (const data::TrackerRow& r : rows) {
    TrackerNode n;
    n.q_mm = r.cmd_mm[axis];
    n.p_mm = {r.tracker_mm[0], r.tracker_mm[1], r.tracker_mm[2]};
    n.printed_cos = {r.cos[0], r.cos[1], r.cos[2]};
    out.push_back(n);
  }
  return out;
}

Vec3 SolveOrThrow(const Mat3& g, const Vec3& b) {
  Vec3 x;
  if (!Solve(g, b, &x)) throw std::runtime_error("tracker: singular direction matrix");
  return x;
}

}  // namespace

void ValidateTrackerData(const TrackerData& data) {
  for (int a = 0; a < 3; ++a) {
    const auto& line = data.lines[static_cast<std::size_t>(a)];
    if (line.size() < 3) {
      throw std::invalid_argument(std::string("tracker: the ") + AxisName(a) +
                                  " line needs at least 3 nodes");
    }
    if (line[0].q_mm != 0.0) {
      throw std::invalid_argument(std::string("tracker: the ") + AxisName(a) +
                                  " line must start at the origin (commanded 0)");
    }
    const double h = line[1].q_mm - line[0].q_mm;
    if (!(h > 0.0)) {
      throw std::invalid_argument(std::string("tracker: the ") + AxisName(a) +
                                  " line must increase");
    }
    for (std::size_t i = 0; i < line.size(); ++i) {
      const TrackerNode& n = line[i];
      if (!std::isfinite(n.q_mm) || !std::isfinite(Norm(n.p_mm))) {
        throw std::invalid_argument(std::string("tracker: non-finite node on the ") + AxisName(a) +
                                    " line");
      }
      if (std::fabs(n.q_mm - h * static_cast<double>(i)) > 1e-9) {
        throw std::invalid_argument(std::string("tracker: the ") + AxisName(a) +
                                    " line is not equally spaced at node " + std::to_string(i));
      }
    }
  }
}

TrackerData S500Tracker315() {
  TrackerData d;
  d.name = "STAN S500 laser tracker, 315 mm cube (Tables 2.10-2.12)";
  d.lines = {Line(data::kTable2_10, 0), Line(data::kTable2_11, 1), Line(data::kTable2_12, 2)};
  d.has_printed_cosines = true;
  return d;
}

TrackerData S500Tracker240() {
  TrackerData d;
  d.name = "STAN S500 laser tracker, 240 mm cube (Tables 2.6-2.8)";
  d.lines = {Line(data::kTable2_6, 0), Line(data::kTable2_7, 1), Line(data::kTable2_8, 2)};
  d.has_printed_cosines = true;
  return d;
}

TrackerModel::TrackerModel(const TrackerData& data, const TrackerOptions& options)
    : data_(data), options_(options) {
  ValidateTrackerData(data_);
  if (options_.cosines == CosineSource::kPrinted && !data_.has_printed_cosines) {
    throw std::invalid_argument("tracker: printed cosines requested but the data has none");
  }
  for (int a = 0; a < 3; ++a) {
    const auto& line = data_.lines[static_cast<std::size_t>(a)];
    step_mm_[static_cast<std::size_t>(a)] = line[1].q_mm - line[0].q_mm;
    auto& cc = cc_[static_cast<std::size_t>(a)];
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Vec3 d = line[i + 1].p_mm - line[i].p_mm;
      switch (options_.cosines) {
        case CosineSource::kPrinted:
          cc.push_back(line[i + 1].printed_cos);
          break;
        case CosineSource::kSigned: {
          const double len = Norm(d);
          if (!(len > 0.0)) throw std::invalid_argument("tracker: two equal consecutive nodes");
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
    auto& cum = cum_[static_cast<std::size_t>(a)];
    cum.assign(1, Vec3{});
    for (int i = 0; i < intervals(a); ++i) {
      cum.push_back(cum.back() + step_mm_[static_cast<std::size_t>(a)] * interval_vector(a, i));
    }
  }
  if (options_.static_interval < 0 || options_.static_interval >= intervals(0) ||
      options_.static_interval >= intervals(1) || options_.static_interval >= intervals(2)) {
    throw std::invalid_argument("tracker: static interval outside the data");
  }
  r01_ = options_.origin == OriginSource::kMeasured ? data_.lines[0][0].p_mm
                                                    : OriginFromXInterval(options_.static_interval);
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

TrackerStaticResult TrackerModel::Static(const Vec3& target_mm) const {
  const int s = options_.static_interval;
  TrackerStaticResult out;
  out.r01_mm = r01_;
  out.g = Mat3::FromColumns(interval_vector(0, s), interval_vector(1, s), interval_vector(2, s));
  out.command_mm = SolveOrThrow(out.g, target_mm - out.r01_mm);  // (2.11)
  return out;
}

TrackerIntervalResult TrackerModel::Interval(const Vec3& target_mm) const {
  TrackerIntervalResult out;
  for (int a = 0; a < 3; ++a) out.n[static_cast<std::size_t>(a)] = CellIndex(a, target_mm[a]);
  out.r01_mm = OriginFromXInterval(out.n[0]);
  out.g = Mat3::FromColumns(interval_vector(0, out.n[0]), interval_vector(1, out.n[1]),
                            interval_vector(2, out.n[2]));
  out.command_mm = SolveOrThrow(out.g, target_mm - out.r01_mm);
  return out;
}

TrackerQuasiResult TrackerModel::QuasiDifferential(const Vec3& target_mm) const {
  TrackerQuasiResult out;
  out.r_mm = r01_;
  for (int a = 0; a < 3; ++a) {
    const int n = CellIndex(a, target_mm[a]);
    out.n[static_cast<std::size_t>(a)] = n;
    out.r_mm += cum_[static_cast<std::size_t>(a)][static_cast<std::size_t>(n)];
  }
  out.g = Mat3::FromColumns(interval_vector(0, out.n[0]), interval_vector(1, out.n[1]),
                            interval_vector(2, out.n[2]));
  out.gamma_mm = SolveOrThrow(out.g, target_mm - out.r_mm);
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
