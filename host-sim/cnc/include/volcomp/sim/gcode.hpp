// A small G-code reader for the simulated CNC: the subset that test programs and simple part
// programs use (the programs `volcomp program positioning|diagonal` write, and hand-written ones).
//
// Accepted (case-insensitive; N line numbers, "( ... )" and ";" comments ignored):
//   G0 rapid, G1 linear at feed F (mm/min), G2/G3 arcs clockwise/counter-clockwise at feed F, all
//   modal; X Y Z coordinates in mm; arcs in the G17 (X-Y), G18 (Z-X) or G19 (Y-Z) plane (modal),
//   centre by I J K (offsets from the start, always incremental; only the plane's two) or radius
//   R (> 0: at most 180 degrees, < 0: more); an arc with no coordinate is a full circle (I J K)
//   G4 P<seconds> dwell
//   G90 absolute / G91 incremental coordinates, G21 mm (G20 inches is refused),
//   G40 G49 G54 G61 G64 G80 G94 accepted and ignored (the CNC's junctions: docs/simulator.md)
//   M2 / M30 end of program (later lines are ignored), M0 M1 M3 M4 M5 M8 M9 ignored
// Anything else is refused (kInputInvalid, "source:line: ..."), so a program that would do
// something the simulator does not model is never run half-understood.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/sim/path.hpp"

namespace volcomp::sim {

struct ProgramBlock {
  enum class Kind { kRapid, kLinear, kArc, kDwell };
  Kind kind = Kind::kRapid;
  std::array<double, 3> value_mm = {0, 0, 0};  // coordinates given on the line
  std::array<bool, 3> has = {false, false, false};
  bool incremental = false;                            // G91: value_mm are distances
  double feed_mm_s = 0;                                // kLinear, kArc
  bool clockwise = false;                              // kArc: G2
  int plane = 17;                                      // kArc: 17, 18 or 19
  std::array<double, 3> centre_offset_mm = {0, 0, 0};  // kArc: I J K
  std::array<bool, 3> has_offset = {false, false, false};
  bool radius_form = false;  // kArc: R given
  double radius_mm = 0;      // kArc: R
  double dwell_s = 0;        // kDwell
  int line = 0;              // 1-based source line
};

using Program = std::vector<ProgramBlock>;

/// Parses a program; `source` names it in failure messages.
Expected<Program> ParseGcode(const std::string& text, const std::string& source = "<program>");

/// The path of motion block `b` started at `position_mm`: its absolute end point with every
/// coordinate rounded to whole steps of `step_mm` (> 0), and its arc words.
PathRequest RequestOf(const ProgramBlock& b, const Point3& position_mm, const Point3& step_mm);

/// Walks `program` from `start_mm` and resolves every arc (PathSegment::Resolve); the first
/// failure is returned as "source:line: ..." (kInputInvalid).
Outcome CheckProgramPaths(const Program& program,
                          const Point3& start_mm,
                          const Point3& step_mm,
                          const std::string& source = "<program>");

}  // namespace volcomp::sim
