// A small G-code reader for the simulated CNC: the subset that test programs and simple part
// programs use (the programs `volcomp program positioning|diagonal` write, and hand-written ones).
//
// Accepted (case-insensitive; N line numbers, "( ... )" and ";" comments ignored):
//   G0 rapid, G1 linear at feed F (mm/min), both modal; X Y Z coordinates in mm
//   G4 P<seconds> dwell
//   G90 absolute / G91 incremental coordinates, G21 mm (G20 inches is refused),
//   G17 G40 G49 G54 G61 G64 G80 G94 accepted and ignored (exact stop is always used)
//   M2 / M30 end of program (later lines are ignored), M0 M1 M3 M4 M5 M8 M9 ignored
// Anything else is refused (kInputInvalid, "source:line: ..."), so a program that would do
// something the simulator does not model is never run half-understood.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::sim {

struct ProgramBlock {
  enum class Kind { kRapid, kLinear, kDwell };
  Kind kind = Kind::kRapid;
  std::array<double, 3> value_mm = {0, 0, 0};  // coordinates given on the line
  std::array<bool, 3> has = {false, false, false};
  bool incremental = false;  // G91: value_mm are distances
  double feed_mm_s = 0;      // kLinear
  double dwell_s = 0;        // kDwell
  int line = 0;              // 1-based source line
};

using Program = std::vector<ProgramBlock>;

/// Parses a program; `source` names it in failure messages.
Expected<Program> ParseGcode(const std::string& text, const std::string& source = "<program>");

}  // namespace volcomp::sim
