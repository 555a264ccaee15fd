// LinuxCNC's machine unit for linear joints, as its INI file says it in [TRAJ]LINEAR_UNITS: the
// one reading of that value for the native HAL component (`loadrt volcomp units=...`) and the PC
// tool (`volcomp export linuxcnc --ini`, which writes compensation files in machine units).
// The words are those of LinuxCNC's INI documentation and sample configurations (mm, metric;
// inch, in, imperial), any case; a number is machine units per mm, as LinuxCNC also reads it
// (1.0 for mm, 1/25.4 ≈ 0.03937 for inch; within 1e-4).
#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace volcomp::hosted {

/// Millimetres per machine unit (1 or 25.4) for a LINEAR_UNITS value, or nullopt for a value
/// that is neither mm nor inch (the caller names it in its message).
inline std::optional<double> LinuxcncMmPerLinearUnit(const std::string& value) {
  std::string t;
  for (const char c : value) t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (t == "mm" || t == "metric" || t == "millimeter" || t == "millimeters" || t == "millimetre" ||
      t == "millimetres") {
    return 1.0;
  }
  if (t == "inch" || t == "in" || t == "inches" || t == "imperial") return 25.4;
  char* end = nullptr;
  const double per_mm = std::strtod(t.c_str(), &end);
  if (t.empty() || end == nullptr || *end != '\0') return std::nullopt;
  if (std::fabs(per_mm - 1.0) < 1e-4) return 1.0;
  if (std::fabs(per_mm * 25.4 - 1.0) < 1e-4) return 25.4;
  return std::nullopt;
}

}  // namespace volcomp::hosted
