// A chain of path segments (lines and arcs joined tangentially) run as one move of the simulated
// CNC: one trapezoidal speed profile over the chain's whole length, and for every axis the step
// times at which the axis's nearest step to the ideal path changes (a step when the path crosses
// the half-way point between two steps), so the CNC's count is the path rounded to whole steps at
// every instant. Virtual time in ns; positions in steps of the machine frame.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "volcomp/sim/path.hpp"
#include "volcomp/sim/trapezoid.hpp"

namespace volcomp::sim {

class PathMotion {
 public:
  /// Preconditions: `segments` non-empty and joined (each starts where the previous ends), the
  /// first starting at `start_steps` * `step_mm`; `speed_mm_s` > 0, `accel_mm_s2` > 0.
  /// `end_steps`: the programmed end point (the chain's end point rounded to steps; an arc's end
  /// may differ from it by its radius mismatch, closed by steps at the end of the move).
  PathMotion(std::vector<PathSegment> segments,
             const std::array<int64_t, 3>& start_steps,
             const std::array<int64_t, 3>& end_steps,
             const Point3& step_mm,
             double speed_mm_s,
             double accel_mm_s2,
             uint64_t start_ns);

  uint64_t end_ns() const { return end_ns_; }
  double length_mm() const { return profile_.length_mm(); }
  double peak_speed_mm_s() const { return profile_.peak_speed_mm_s(); }
  /// The path length travelled (mm) at virtual time `t_ns`.
  double PathLengthAt(uint64_t t_ns) const;
  /// The segment the path is on at virtual time `t_ns`.
  const PathSegment& SegmentAt(uint64_t t_ns) const;
  /// The ideal position (mm) at virtual time `t_ns`.
  Point3 PositionAt(uint64_t t_ns) const;

  /// Emits, in time order per axis, every step due at or before `t_ns` through
  /// `emit(axis, time_ns, dir)`; returns true when every step of the move has been emitted.
  template <class Emit>
  bool EmitUntil(uint64_t t_ns, Emit&& emit) {
    bool done = true;
    for (int a = 0; a < 3; ++a) {
      Axis& x = axes_[static_cast<size_t>(a)];
      while (x.due && x.next_ns <= t_ns) {
        emit(a, x.next_ns, x.next_dir);
        Advance(a);
      }
      done = done && !x.due;
    }
    return done;
  }

 private:
  struct Axis {
    int64_t p = 0;       // current step position
    int64_t end = 0;     // programmed end
    size_t seg = 0;      // segment of the last event
    double s_local = 0;  // path length within it of the last event
    bool due = false;    // another step is due
    uint64_t next_ns = 0;
    int next_dir = 1;
  };
  size_t SegmentIndex(double s_mm) const;  // the segment holding path length s
  void Advance(int a);
  void FindNext(int a);
  uint64_t TimeOf(size_t seg, double s_local) const;

  std::vector<PathSegment> segments_;
  std::vector<double> offset_mm_;  // path length before each segment
  Point3 step_mm_;
  TrapezoidProfile profile_;
  uint64_t start_ns_ = 0;
  uint64_t end_ns_ = 0;
  std::array<Axis, 3> axes_;
};

}  // namespace volcomp::sim
