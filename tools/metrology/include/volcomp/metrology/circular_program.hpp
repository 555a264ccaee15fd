// The ISO 230-4 circular test program (G-code, RS274/NGC as LinuxCNC reads it): the nominal
// circle run counter-clockwise (G3) and then clockwise (G2), each as a run-in arc, the measured
// 360° and a run-out arc, all tangent and blended (G64), so the feed is constant over the whole
// measured circle and the accelerations at the start, the reversal and the end lie outside it
// (as ballbar practice does). The CW run-in retraces the CCW run-out, so the program reverses
// once, outside the measurement.
//
// Angles, as `evaluate circular` reads them: counter-clockwise (the sense of G3) from the plane's
// first axis towards its second, seen from the plane's positive normal: XY (G17) from +X towards
// +Y; ZX (G18, "XZ") from +Z towards +X; YZ (G19) from +Y towards +Z. Lengths in mm, feed in
// mm/min. An impossible plan is a failure (kInvalidArgument) naming the option's subject.
#pragma once

#include <array>
#include <string>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::metrology {

enum class CircularPlane { kXY, kZX, kYZ };

struct CircularProgramOptions {
  CircularPlane plane = CircularPlane::kXY;
  std::array<double, 3> centre_mm{0.0, 0.0, 0.0};  // X, Y, Z of the circle's centre
  double radius_mm = 0.0;                          // > 0
  double feed_mm_min = 1000.0;                     // > 0
  double start_angle_deg = 0.0;                    // where each measured 360° begins and ends
  double run_deg = 90.0;                           // run-in and run-out arc, (0, 180]
  bool pause = false;  // M0 at the start point (fit the ballbar, then cycle start)
  bool inch = false;   // G20: coordinates / 25.4 with 5 decimals (0.254 µm), feed / 25.4 in/min
                       // (3 decimals); the options above stay in mm and mm/min
};

/// "XY", "XZ" (= "ZX") or "YZ"; the plane's G-code word is G17, G18, G19.
const char* CircularPlaneName(CircularPlane plane);

/// The program text (ends with M2).
Expected<std::string> EmitCircularProgram(const CircularProgramOptions& options);

}  // namespace volcomp::metrology
