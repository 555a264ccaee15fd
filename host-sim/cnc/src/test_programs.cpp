// Measurement programs as G-code.
#include "volcomp/sim/test_programs.hpp"

#include <cmath>
#include <cstdio>

#include "volcomp/metrology/diagonal.hpp"

namespace volcomp::sim {
namespace {

std::string Coords(const Point3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "X%.4f Y%.4f Z%.4f", p[0], p[1], p[2]);
  return buf;
}

std::string Seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", s);
  return buf;
}

Point3 OnLine(const Point3& origin, const Point3& dir, double along) {
  return {origin[0] + along * dir[0], origin[1] + along * dir[1], origin[2] + along * dir[2]};
}

// A line test along machine axis `axis` (0..2) through `through`.
Expected<TestProgram> AxisLineProgram(const std::string& name,
                                      int axis,
                                      const Point3& through,
                                      const std::vector<double>& targets_mm,
                                      const CycleOptions& options) {
  if (axis < 0 || axis > 2) return Fail(Error::kInvalidArgument, name + ": axis must be 0..2");
  Point3 origin = through;
  origin[static_cast<size_t>(axis)] = 0;
  Point3 dir = {0, 0, 0};
  dir[static_cast<size_t>(axis)] = 1;
  return LineTestProgram(name + " " + "XYZ"[axis], origin, dir, targets_mm, options);
}

}  // namespace

Expected<TestProgram> LineTestProgram(const std::string& name,
                                      const Point3& origin_mm,
                                      const Point3& direction,
                                      const std::vector<double>& targets_mm,
                                      const CycleOptions& options) {
  TestProgram p;
  p.name = name;
  p.origin_mm = origin_mm;
  p.direction = direction;
  VOLCOMP_TRY_ASSIGN(const std::vector<metrology::CycleMove> moves,
                     metrology::BuildCycle(targets_mm, metrology::Cycle::kLinear, options.runs,
                                           options.overrun_mm));
  std::string g = "(" + name + ": linear cycle, " + std::to_string(targets_mm.size()) +
                  " targets, " + std::to_string(options.runs) + " runs each way)\n";
  g += "(the instrument is zeroed at the first stop and read at the end of every G4)\n";
  char feed[32];
  std::snprintf(feed, sizeof feed, "F%.0f", options.feed_mm_s * 60);
  g += "G21 G90 G94\n";
  bool first = true;
  for (const metrology::CycleMove& m : moves) {
    const Point3 pt = OnLine(origin_mm, direction, m.position);
    if (first) {
      g += "G0 " + Coords(pt) + " (datum)\nG4 P" + Seconds(options.dwell_s) + "\n" + feed + "\n";
      MeasuredStop s;
      s.point_mm = pt;
      s.along_mm = m.position;
      s.datum = true;
      p.stops.push_back(s);
      first = false;
      continue;
    }
    g += "G1 " + Coords(pt);
    if (m.measure) {
      g += " (P" + std::to_string(m.target) + " " + metrology::DirectionName(m.approach) + " run " +
           std::to_string(m.run) + ")\nG4 P" + Seconds(options.dwell_s) + "\n";
      MeasuredStop s;
      s.point_mm = pt;
      s.along_mm = m.position;
      s.approach = m.approach;
      s.run = m.run;
      s.target = m.target;
      p.stops.push_back(s);
    } else {
      g += "\n";
    }
  }
  g += "M2\n";
  p.gcode = g;
  return p;
}

Expected<TestProgram> GostAxisProgram(int axis,
                                      const Point3& line_point_mm,
                                      const std::vector<double>& targets_mm,
                                      const CycleOptions& options) {
  return AxisLineProgram("GOST 27843", axis, line_point_mm, targets_mm, options);
}

Expected<TestProgram> DiagonalProgram(const std::string& name,
                                      const Point3& p1_mm,
                                      const Point3& p2_mm,
                                      double increment_mm,
                                      const CycleOptions& options) {
  VOLCOMP_TRY_ASSIGN(const metrology::DiagonalPlan plan,
                     metrology::PlanDiagonal({p1_mm[0], p1_mm[1], p1_mm[2]},
                                             {p2_mm[0], p2_mm[1], p2_mm[2]}, increment_mm));
  const Point3 dir = {plan.travel_mm.x / plan.length_mm, plan.travel_mm.y / plan.length_mm,
                      plan.travel_mm.z / plan.length_mm};
  return LineTestProgram(name, p1_mm, dir, plan.distances, options);
}

TestProgram PointSetProgram(const std::string& name,
                            const std::vector<Point3>& points_mm,
                            double dwell_s,
                            double approach_mm) {
  TestProgram p;
  p.name = name;
  std::string g =
      "(" + name + ": " + std::to_string(points_mm.size()) + " points; the first is the datum)\n";
  if (approach_mm > 0) {
    g += "(each approached from " + Seconds(approach_mm) + " mm below on every axis)\n";
  }
  g += "G21 G90 G94\n";
  for (size_t i = 0; i < points_mm.size(); ++i) {
    const Point3& q = points_mm[i];
    if (approach_mm > 0) {
      g += "G0 " + Coords({q[0] - approach_mm, q[1] - approach_mm, q[2] - approach_mm}) + "\n";
    }
    g += "G0 " + Coords(q) + "\nG4 P" + Seconds(dwell_s) + "\n";
    MeasuredStop s;
    s.point_mm = points_mm[i];
    s.datum = i == 0;
    s.target = static_cast<int>(i);
    s.run = 1;
    p.stops.push_back(s);
  }
  g += "M2\n";
  p.gcode = g;
  if (!points_mm.empty()) p.origin_mm = points_mm[0];
  return p;
}

Expected<TestProgram> ParametricProgram(int axis,
                                        const Point3& reference_mm,
                                        const std::vector<double>& positions_mm,
                                        const CycleOptions& options) {
  return AxisLineProgram("parametric", axis, reference_mm, positions_mm, options);
}

std::vector<BodyDiagonal> BodyDiagonals(const Point3& lo_mm, const Point3& hi_mm) {
  std::vector<BodyDiagonal> out;
  // Start corners -X-Y-Z, +X-Y-Z, -X+Y-Z, +X+Y-Z (bit a set = + on axis a), each to its opposite.
  for (int c : {0, 1, 2, 3}) {
    BodyDiagonal d;
    for (int a = 0; a < 3; ++a) {
      const bool plus = (c >> a) & 1;
      const size_t i = static_cast<size_t>(a);
      d.p1[i] = plus ? hi_mm[i] : lo_mm[i];
      d.p2[i] = plus ? lo_mm[i] : hi_mm[i];
      d.name += plus ? "+" : "-";
      d.name += "XYZ"[a];
    }
    out.push_back(d);
  }
  return out;
}

}  // namespace volcomp::sim
