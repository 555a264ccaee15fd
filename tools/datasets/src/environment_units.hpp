// The unit of a laser's environment reading recognised by its range (issue 25 item 3, "units as
// the shop has them"): an .rtl records no unit, and LaserXL run in imperial units writes °F and
// (presumably) inHg where a metric setup writes °C and kPa. The ranges do not overlap for what a
// machine shop can be:
//   - temperature: at most 45 is °C (no shop is at 45 °C); above 45 is °F, up to 113 °F (= 45 °C;
//     50–104 °F is typical). Anything else, or a start and end on either side of 45, is neither.
//   - air pressure (80–110 kPa covers sea level to about 2000 m and every weather): kPa 80–110,
//     hPa (mbar) 800–1100, mmHg 600–825, inHg 23.6–32.5. 800–825 is both hPa and mmHg; it is read
//     as hPa (a factory at 1700–2000 m), since 800–825 mmHg (107–110 kPa) only record weather
//     gives; the caller says which unit was assumed.
// Conversions are exact by definition: °C = (°F − 32)/1.8; 1 hPa = 0.1 kPa; 1 mmHg =
// 133.322387415 Pa (conventional, NIST SP 811 B.8); 1 inHg = 25.4 mmHg = 3.386389 kPa.
#pragma once

#include <optional>
#include <string>

namespace volcomp::datasets {

/// At most this is °C; above it °F.
inline constexpr double kHighestShopCelsius = 45.0;
/// The highest °F taken for a shop temperature: 113 °F = 45 °C.
inline constexpr double kHighestShopFahrenheit = 113.0;

enum class TemperatureUnit { kCelsius, kFahrenheit };

/// The unit of a start/end pair: °C when both are ≤ 45, °F when both are above 45 and ≤ 113;
/// nullopt otherwise.
std::optional<TemperatureUnit> RecogniseTemperature(double start, double end);

/// (f − 32)/1.8.
double CelsiusFromFahrenheit(double fahrenheit);

/// A pressure unit and the range it is recognised in.
struct PressureUnit {
  const char* name;  // "kPa", "hPa (mbar)", "mmHg", "inHg"
  double lowest;     // the range recognised, in this unit
  double highest;
  double kpa_per_unit;
};

/// The first unit (kPa, hPa, mmHg, inHg) whose range holds both values; nullptr when none does.
const PressureUnit* RecognisePressure(double start, double end);

/// "kPa 80–110, hPa (mbar) 800–1100, mmHg 600–825 or inHg 23.6–32.5", for refusals.
std::string PressureRangesText();

}  // namespace volcomp::datasets
