// ISO 230-4 circular test programs.
#include "volcomp/metrology/circular_program.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "volcomp/metrology/inch.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/tools/math_constants.hpp"

namespace volcomp::metrology {
namespace {

using tools::kPi;
constexpr int kDecimals = 4;

// The plane's two axes (indices into X, Y, Z) in the order that makes G3 counter-clockwise, its
// normal, and the G-code words.
struct PlaneAxes {
  int first, second, normal;
  const char* gcode;
};

PlaneAxes AxesOf(CircularPlane plane) {
  switch (plane) {
    case CircularPlane::kZX:
      return {2, 0, 1, "G18"};
    case CircularPlane::kYZ:
      return {1, 2, 0, "G19"};
    case CircularPlane::kXY:
    default:
      return {0, 1, 2, "G17"};
  }
}

const char* const kAxisWord[3] = {"X", "Y", "Z"};
const char* const kOffsetWord[3] = {"I", "J", "K"};

constexpr int kInchDecimals = 5;

// Fixed decimals; what rounds to zero is written 0.0000, never -0.0000.
std::string Num(double v) { return report::FormatFixed(std::fabs(v) < 5e-5 ? 0.0 : v, kDecimals); }

// A length of the program (mm, or inches with `inch`), likewise never -0.
std::string Length(double mm, bool inch) {
  if (!inch) return Num(mm);
  const double in = mm / kMmPerInch;
  return report::FormatFixed(std::fabs(in) < 5e-6 ? 0.0 : in, kInchDecimals);
}

class Writer {
 public:
  Writer(const CircularProgramOptions& o) : o_(o), axes_(AxesOf(o.plane)) {}

  // The point at `angle_deg` on the circle, as X Y Z words.
  std::string Point(double angle_deg) const {
    const auto p = PointAt(angle_deg);
    return std::string("X") + Length(p[0], o_.inch) + " Y" + Length(p[1], o_.inch) + " Z" +
           Length(p[2], o_.inch);
  }

  // An arc from `from_deg` sweeping `sweep_deg` (> 0) in the given sense: its end point in the
  // plane and the centre's offset from the start (I/J/K of the plane's axes).
  std::string Arc(bool ccw, double from_deg, double sweep_deg, const std::string& comment) const {
    const double to = ccw ? from_deg + sweep_deg : from_deg - sweep_deg;
    const auto start = PointAt(from_deg);
    const auto end = sweep_deg >= 360.0 ? start : PointAt(to);  // a full circle ends exactly
    std::ostringstream s;
    s << (ccw ? "G3 " : "G2 ");
    // Words in the order X Y Z, I J K, whatever the plane's order.
    const int lo = std::min(axes_.first, axes_.second), hi = std::max(axes_.first, axes_.second);
    for (int a : {lo, hi}) {
      s << kAxisWord[a] << Length(end[static_cast<std::size_t>(a)], o_.inch) << " ";
    }
    for (int a : {lo, hi}) {
      s << kOffsetWord[a]
        << Length(o_.centre_mm[static_cast<std::size_t>(a)] - start[static_cast<std::size_t>(a)],
                  o_.inch)
        << " ";
    }
    s << "(" << comment << ")\n";
    return s.str();
  }

 private:
  std::array<double, 3> PointAt(double angle_deg) const {
    std::array<double, 3> p = o_.centre_mm;
    const double t = angle_deg * kPi / 180.0;
    p[static_cast<std::size_t>(axes_.first)] += o_.radius_mm * std::cos(t);
    p[static_cast<std::size_t>(axes_.second)] += o_.radius_mm * std::sin(t);
    return p;
  }

  const CircularProgramOptions& o_;
  PlaneAxes axes_;
};

std::string AngleSense(CircularPlane plane) {
  const PlaneAxes a = AxesOf(plane);
  return std::string("angles counter-clockwise from +") + kAxisWord[a.first] + " towards +" +
         kAxisWord[a.second] + " seen from +" + kAxisWord[a.normal];
}

}  // namespace

const char* CircularPlaneName(CircularPlane plane) {
  switch (plane) {
    case CircularPlane::kZX:
      return "XZ";
    case CircularPlane::kYZ:
      return "YZ";
    case CircularPlane::kXY:
    default:
      return "XY";
  }
}

Expected<std::string> EmitCircularProgram(const CircularProgramOptions& o) {
  if (!(o.radius_mm > 0.0) || !std::isfinite(o.radius_mm)) {
    return Fail(Error::kInvalidArgument, "the radius must be positive");
  }
  if (!(o.feed_mm_min > 0.0) || !std::isfinite(o.feed_mm_min)) {
    return Fail(Error::kInvalidArgument, "the feed must be positive");
  }
  if (!(o.run_deg > 0.0 && o.run_deg <= 180.0)) {
    return Fail(Error::kInvalidArgument, "the run-in/run-out arc must be within (0, 180] degrees");
  }
  for (double c : o.centre_mm) {
    if (!std::isfinite(c)) return Fail(Error::kInvalidArgument, "the centre must be finite");
  }
  if (!std::isfinite(o.start_angle_deg)) {
    return Fail(Error::kInvalidArgument, "the start angle must be finite");
  }
  const Writer w(o);
  const PlaneAxes axes = AxesOf(o.plane);
  const double a = o.start_angle_deg, run = o.run_deg;
  const std::string run_text = report::FormatNumber(run);
  std::ostringstream g;
  g << "(ISO 230-4 circular test: plane " << CircularPlaneName(o.plane) << " [" << axes.gcode
    << "], centre X" << Num(o.centre_mm[0]) << " Y" << Num(o.centre_mm[1]) << " Z"
    << Num(o.centre_mm[2]) << ", radius " << Num(o.radius_mm) << " mm, feed "
    << report::FormatNumber(o.feed_mm_min) << " mm/min)\n";
  g << "(" << AngleSense(o.plane) << "; each direction measured over 360 deg from "
    << report::FormatNumber(a) << " deg, CCW [G3] then CW [G2])\n";
  g << "(run-in and run-out arcs of " << run_text
    << " deg keep the acceleration outside the measured circle; G64 blends the arcs)\n";
  if (o.inch) g << "(program in inches: G20, coordinates in in, feed in in/min)\n";
  g << "(generated by volcomp)\n";
  g << (o.inch ? "G20" : "G21") << " G90 G94 " << axes.gcode << " G64\n";
  g << "G0 " << w.Point(a - run) << " (start of the CCW run-in)\n";
  if (o.pause) g << "M0 (fit the ballbar, then cycle start)\n";
  g << "F"
    << (o.inch ? report::FormatFixed(o.feed_mm_min / kMmPerInch, 3)
               : report::FormatNumber(o.feed_mm_min))
    << "\n";
  g << w.Arc(true, a - run, run, "CCW run-in " + run_text + " deg");
  g << w.Arc(true, a, 360.0, "CCW measured 360 deg");
  g << w.Arc(true, a, run, "CCW run-out " + run_text + " deg");
  g << w.Arc(false, a + run, run, "CW run-in " + run_text + " deg");
  g << w.Arc(false, a, 360.0, "CW measured 360 deg");
  g << w.Arc(false, a, run, "CW run-out " + run_text + " deg");
  g << "M2\n";
  return g.str();
}

}  // namespace volcomp::metrology
