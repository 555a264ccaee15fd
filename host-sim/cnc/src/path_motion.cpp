// Step times of a chain of path segments.
#include "volcomp/sim/path_motion.hpp"

#include <cmath>

namespace volcomp::sim {

PathMotion::PathMotion(std::vector<PathSegment> segments,
                       const std::array<int64_t, 3>& start_steps,
                       const std::array<int64_t, 3>& end_steps,
                       const Point3& step_mm,
                       double speed_mm_s,
                       double accel_mm_s2,
                       uint64_t start_ns)
    : segments_(std::move(segments)), step_mm_(step_mm), profile_(0, 1, 1), start_ns_(start_ns) {
  double total = 0;
  for (const PathSegment& s : segments_) {
    offset_mm_.push_back(total);
    total += s.length_mm();
  }
  profile_ = TrapezoidProfile(total, speed_mm_s, accel_mm_s2);
  end_ns_ = start_ns + static_cast<uint64_t>(std::ceil(profile_.duration_s() * 1e9));
  for (size_t a = 0; a < 3; ++a) {
    axes_[a].p = start_steps[a];
    axes_[a].end = end_steps[a];
    FindNext(static_cast<int>(a));
  }
}

uint64_t PathMotion::TimeOf(size_t seg, double s_local) const {
  return start_ns_ +
         static_cast<uint64_t>(std::ceil(profile_.TimeAt(offset_mm_[seg] + s_local) * 1e9));
}

double PathMotion::PathLengthAt(uint64_t t_ns) const {
  const double t = t_ns <= start_ns_ ? 0.0 : static_cast<double>(t_ns - start_ns_) * 1e-9;
  return profile_.PositionAt(t);
}

size_t PathMotion::SegmentIndex(double s_mm) const {
  size_t i = 0;
  while (i + 1 < segments_.size() && offset_mm_[i + 1] <= s_mm) ++i;
  return i;
}

const PathSegment& PathMotion::SegmentAt(uint64_t t_ns) const {
  return segments_[SegmentIndex(PathLengthAt(t_ns))];
}

Point3 PathMotion::PositionAt(uint64_t t_ns) const {
  const double s = PathLengthAt(t_ns);
  const size_t i = SegmentIndex(s);
  return segments_[i].PointAt(s - offset_mm_[i]);
}

void PathMotion::FindNext(int a) {
  Axis& x = axes_[static_cast<size_t>(a)];
  const double step = step_mm_[static_cast<size_t>(a)];
  const double up = (static_cast<double>(x.p) + 0.5) * step;
  const double down = (static_cast<double>(x.p) - 0.5) * step;
  for (; x.seg < segments_.size(); ++x.seg, x.s_local = 0) {
    const PathSegment& s = segments_[x.seg];
    const double s_up = s.NextCrossing(a, x.s_local, up, 1);
    const double s_down = s.NextCrossing(a, x.s_local, down, -1);
    if (s_up < 0 && s_down < 0) continue;
    const bool go_up = s_down < 0 || (s_up >= 0 && s_up <= s_down);
    x.s_local = go_up ? s_up : s_down;
    x.next_dir = go_up ? 1 : -1;
    x.next_ns = TimeOf(x.seg, x.s_local);
    x.due = true;
    return;
  }
  // The path is done; close the difference to the programmed end (an arc's radius mismatch).
  x.seg = segments_.size();
  x.due = x.p != x.end;
  x.next_dir = x.end > x.p ? 1 : -1;
  x.next_ns = end_ns_;
}

void PathMotion::Advance(int a) {
  Axis& x = axes_[static_cast<size_t>(a)];
  x.p += x.next_dir;
  if (x.seg < segments_.size()) {
    FindNext(a);
  } else {
    x.due = x.p != x.end;
  }
}

}  // namespace volcomp::sim
