// Mathematical constants the PC tool's libraries share (the hosted side; lib/ has its own
// fixed-point and float forms).
#pragma once

namespace volcomp::tools {

/// π to double precision.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace volcomp::tools
