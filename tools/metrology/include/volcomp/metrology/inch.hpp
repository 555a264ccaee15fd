// The inch, for inch data files and inch (G20) programs.
#pragma once

namespace volcomp::metrology {

/// 1 in = 25.4 mm exactly (the international inch of 1959; NIST SP 811 B.8).
inline constexpr double kMmPerInch = 25.4;

/// 1 µin = 0.0254 µm (the same definition, a millionth of each).
inline constexpr double kMicrometresPerMicroinch = kMmPerInch / 1000.0;

}  // namespace volcomp::metrology
