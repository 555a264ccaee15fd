// Environment units recognised by range (environment_units.hpp).
#include "environment_units.hpp"

#include <sstream>

#include "volcomp/metrology/inch.hpp"

namespace volcomp::datasets {
namespace {

constexpr double kKpaPerMmHg = 0.133322387415;  // 133.322387415 Pa, conventional
constexpr double kKpaPerInHg = kKpaPerMmHg * metrology::kMmPerInch;  // 1 inHg = 25.4 mmHg

// hPa before mmHg: 800–825 is read as hPa (environment_units.hpp).
constexpr PressureUnit kPressureUnits[] = {
    {"kPa", 80.0, 110.0, 1.0},
    {"hPa (mbar)", 800.0, 1100.0, 0.1},
    {"mmHg", 600.0, 825.0, kKpaPerMmHg},
    {"inHg", 23.6, 32.5, kKpaPerInHg},
};

bool Within(double v, const PressureUnit& u) { return v >= u.lowest && v <= u.highest; }

}  // namespace

std::optional<TemperatureUnit> RecogniseTemperature(double start, double end) {
  if (start <= kHighestShopCelsius && end <= kHighestShopCelsius) {
    return TemperatureUnit::kCelsius;
  }
  const auto fahrenheit = [](double v) {
    return v > kHighestShopCelsius && v <= kHighestShopFahrenheit;
  };
  if (fahrenheit(start) && fahrenheit(end)) return TemperatureUnit::kFahrenheit;
  return std::nullopt;
}

double CelsiusFromFahrenheit(double fahrenheit) { return (fahrenheit - 32.0) / 1.8; }

const PressureUnit* RecognisePressure(double start, double end) {
  for (const PressureUnit& u : kPressureUnits) {
    if (Within(start, u) && Within(end, u)) return &u;
  }
  return nullptr;
}

std::string PressureRangesText() {
  std::ostringstream s;
  const std::size_t n = sizeof(kPressureUnits) / sizeof(kPressureUnits[0]);
  for (std::size_t k = 0; k < n; ++k) {
    const PressureUnit& u = kPressureUnits[k];
    s << (k == 0       ? ""
          : k + 1 == n ? " or "
                       : ", ")
      << u.name << " " << u.lowest << "–" << u.highest;
  }
  return s.str();
}

}  // namespace volcomp::datasets
