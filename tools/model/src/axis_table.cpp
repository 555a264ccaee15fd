// Piecewise-linear axis error tables.
#include "volcomp/model/axis_table.hpp"

#include <cmath>
#include <string>

namespace volcomp::model {
namespace {

bool Finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

AxisErrorSample Lerp(const AxisErrorSample& a, const AxisErrorSample& b, double t) {
  return {a.linear_um + t * (b.linear_um - a.linear_um),
          a.angular_urad + t * (b.angular_urad - a.angular_urad)};
}

}  // namespace

Expected<AxisErrorTable> AxisErrorTable::Create(std::vector<double> position_mm,
                                                std::vector<AxisErrorSample> rows) {
  const auto invalid = [](const std::string& message) {
    return Fail(Error::kInvalidArgument, "axis table: " + message);
  };
  if (position_mm.size() != rows.size()) return invalid("positions and rows differ in count");
  if (position_mm.size() < 2) return invalid("needs at least 2 rows");
  for (std::size_t i = 0; i < position_mm.size(); ++i) {
    if (!std::isfinite(position_mm[i]) || !Finite(rows[i].linear_um) ||
        !Finite(rows[i].angular_urad)) {
      return invalid("row " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(position_mm[i] > position_mm[i - 1])) {
      return invalid("positions must increase strictly (row " + std::to_string(i) + ")");
    }
  }
  AxisErrorTable t;
  t.position_mm_ = std::move(position_mm);
  t.rows_ = std::move(rows);
  const std::vector<double>& p = t.position_mm_;
  const double h = (p.back() - p.front()) / static_cast<double>(p.size() - 1);
  bool uniform = true;
  for (std::size_t i = 0; i < p.size() && uniform; ++i) {
    uniform = std::fabs(p[i] - (p.front() + h * static_cast<double>(i))) <= 1e-9;
  }
  t.uniform_spacing_mm_ = uniform ? h : 0.0;
  return t;
}

AxisErrorSample AxisErrorTable::Sample(double position_mm) const {
  const std::size_t n = position_mm_.size();
  if (!(position_mm > position_mm_.front())) return rows_.front();
  if (!(position_mm < position_mm_.back())) return rows_.back();
  std::size_t i;
  if (uniform_spacing_mm_ > 0.0) {
    const double f = (position_mm - position_mm_.front()) / uniform_spacing_mm_;
    i = static_cast<std::size_t>(f);
    if (i > n - 2) i = n - 2;
    // Guard against rounding in f so that nodes are hit exactly.
    if (i + 2 < n && position_mm >= position_mm_[i + 1]) ++i;
    if (i > 0 && position_mm < position_mm_[i]) --i;
  } else {
    std::size_t lo = 0, hi = n - 1;  // position_mm_[lo] <= p < position_mm_[hi]
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (position_mm_[mid] <= position_mm) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    i = lo;
  }
  const double t = (position_mm - position_mm_[i]) / (position_mm_[i + 1] - position_mm_[i]);
  if (t == 0.0) return rows_[i];
  return Lerp(rows_[i], rows_[i + 1], t);
}

Expected<AxisErrorTable> AxisErrorTable::Resampled(double step_mm, double max_mm) const {
  if (!(step_mm > 0.0) || !(max_mm > min_mm())) {
    return Fail(Error::kInvalidArgument, "axis table: bad resampling step or range");
  }
  const auto count = static_cast<std::size_t>(std::floor((max_mm - min_mm()) / step_mm + 1e-9));
  std::vector<double> pos;
  std::vector<AxisErrorSample> rows;
  for (std::size_t i = 0; i <= count; ++i) {
    const double p = min_mm() + step_mm * static_cast<double>(i);
    pos.push_back(p);
    rows.push_back(Sample(p));
  }
  return Create(std::move(pos), std::move(rows));
}

}  // namespace volcomp::model
