// The worn machine's temperature sensors (issue 23 item 4): what the board's channels read, which
// is not the heat balance's state. Each sensor sits on a surface that mixes the bodies it touches
// with the air around it (the X screw's nut housing sees the screw and the air, the spindle head's
// sensor the head casting and a little of the cartridge), follows that mix with its own lag (a
// first-order response: housing, glue, sensor body), reads with its own offset (calibration,
// mounting) and noise, and is quantised to the channel's 0.01 K.
//
// Faults for the board's supervision: an open circuit (the converter's "no reading", 0x8000 =
// INT16_MIN) and a stuck converter (the last reading repeated).
//
// Units: temperatures C, readings 0.01 C (int16, the channels' unit), time s.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "volcomp/sim/heat_balance.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim {

struct ThermalSensorParams {
  std::string name;  // the channel's name in a drift test's CSV (T_<name>_C)
  // What the sensor's surface is: weights of the bodies and of the air (sum 1).
  std::array<double, kThermalBodies> body_weight = {};
  double air_weight = 0;
  double lag_s = 60;      // first-order time constant
  double offset_K = 0;    // reads this much high
  double noise_K = 0.02;  // standard deviation of each reading
};

enum class SensorFault { kNone, kOpenCircuit, kStuck };

class ThermalSensor {
 public:
  /// Starts settled on its surface's temperature in `machine` at `ambient_C`.
  ThermalSensor(const ThermalSensorParams& params,
                const HeatBalance& machine,
                double ambient_C,
                uint64_t seed);

  /// Follows the surface for `dt_s` (exact first-order response to the surface temperature now).
  void Step(double dt_s, const HeatBalance& machine, double ambient_C);
  /// A reading now, 0.01 C (noise and the fault applied); INT16_MIN for an open circuit.
  int16_t Read_cC();
  /// The sensor body's temperature (lagged, without offset and noise), C.
  double body_C() const { return body_C_; }

  void InjectFault(SensorFault fault) { fault_ = fault; }
  SensorFault fault() const { return fault_; }
  const ThermalSensorParams& params() const { return p_; }

 private:
  double Surface_C(const HeatBalance& machine, double ambient_C) const;

  ThermalSensorParams p_;
  double body_C_;
  Random rng_;
  SensorFault fault_ = SensorFault::kNone;
  int16_t last_cC_ = 0;
  bool has_last_ = false;
};

/// The worn machine's three sensors: [0] the X screw's nut housing ("screw_x"), [1] the spindle
/// head ("spindle"), [2] the air near the machine ("ambient"). docs/simulator.md "Heat balance".
std::array<ThermalSensorParams, 3> WornMachineSensors();

}  // namespace volcomp::sim
