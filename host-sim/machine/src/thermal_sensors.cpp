#include "volcomp/sim/thermal_sensors.hpp"

#include <climits>
#include <cmath>

namespace volcomp::sim {

ThermalSensor::ThermalSensor(const ThermalSensorParams& params,
                             const HeatBalance& machine,
                             double ambient_C,
                             uint64_t seed)
    : p_(params), body_C_(0), rng_(seed) {
  body_C_ = Surface_C(machine, ambient_C);
}

double ThermalSensor::Surface_C(const HeatBalance& machine, double ambient_C) const {
  double t = p_.air_weight * ambient_C;
  for (int i = 0; i < kThermalBodies; ++i) {
    t += p_.body_weight[static_cast<size_t>(i)] * machine.temperatures_C()[static_cast<size_t>(i)];
  }
  return t;
}

void ThermalSensor::Step(double dt_s, const HeatBalance& machine, double ambient_C) {
  const double surface = Surface_C(machine, ambient_C);
  body_C_ = surface + (body_C_ - surface) * std::exp(-dt_s / p_.lag_s);
}

int16_t ThermalSensor::Read_cC() {
  if (fault_ == SensorFault::kOpenCircuit) return INT16_MIN;
  if (fault_ == SensorFault::kStuck && has_last_) return last_cC_;
  const double t = body_C_ + p_.offset_K + p_.noise_K * rng_.Gaussian();
  last_cC_ = static_cast<int16_t>(std::lround(t * 100.0));
  has_last_ = true;
  return last_cC_;
}

std::array<ThermalSensorParams, 3> WornMachineSensors() {
  std::array<ThermalSensorParams, 3> s;
  s[0].name = "screw_x";
  s[0].body_weight[static_cast<int>(ThermalBody::kXScrew)] = 0.75;
  s[0].air_weight = 0.25;
  s[0].lag_s = 240;
  s[0].offset_K = 0.4;
  s[0].noise_K = 0.03;
  s[1].name = "spindle";
  s[1].body_weight[static_cast<int>(ThermalBody::kHead)] = 0.75;
  s[1].body_weight[static_cast<int>(ThermalBody::kSpindle)] = 0.25;
  s[1].lag_s = 120;
  s[1].offset_K = -0.3;
  s[1].noise_K = 0.03;
  s[2].name = "ambient";
  s[2].air_weight = 1;
  s[2].lag_s = 600;
  s[2].offset_K = 0.2;
  s[2].noise_K = 0.05;
  return s;
}

}  // namespace volcomp::sim
