// The thermal model and the correction it drives (issue 23, docs/thermal.md "The model"): per axis
// a position-independent offset plus a position-dependent slope, each a linear combination of the
// channels' temperature rises over their reference temperatures, the form Siemens (SD43900-43920),
// ISG and Heidenhain use:
//
//   c_a(p) = O_a + S_a * (p - p0_a)               c: the axis's thermal correction, um; p in mm
//   O_a    = sum_j offset_um_per_K[a][j] * (T_j - Tref_j)
//   S_a    = sum_j slope_um_per_K_m[a][j] * (T_j - Tref_j) / 1000     (um per mm of travel)
//
// Like every correction of the table image, c is added to the commanded position (the builder
// fits the coefficients against the measured drift with that sign: a drift of +d is a correction
// of -d). ISO 1's case (a steel scale measuring a steel part both referred to 20 C, the scale
// warmer): slope_um_per_K_m = -11.5 on the scale's channel, Tref 20 C, p0 the scale's zero.
//
// ThermalCorrection runs in the board's main loop at a fixed period (Update()): it evaluates the
// model from the channels and moves the applied offset and slope toward it so that the correction
// changes by at most slew_um_s anywhere on the axis's travel (|dO| + |dS| * reach <= slew * dt).
// What it does when it cannot trust the temperatures (docs/thermal.md, "Faults"):
//   * a channel the model uses is in a fault state: the correction holds its last value for
//     hold_ms, then fades to zero at the slew limit; it comes back at the slew limit once every
//     channel it uses is valid again;
//   * a channel is outside the temperature range the model was calibrated over: the model takes
//     that channel at the range's edge (never extrapolates) and flags it.
// Every state is visible: status() (flags and masks), the applied offset and slope.
//
// No allocation; float arithmetic in Update() (main loop, never the tick path). Turning the applied
// terms into steps for the compensation run is the compensator's side (issue 23 item 2).
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp::thermal {

inline constexpr uint8_t kMaxModelAxes = 6;

struct AxisModel {
  float offset_um_per_K[kMaxChannels] = {};
  float slope_um_per_K_m[kMaxChannels] = {};
  float p0_mm = 0.0f;     // where the slope term is zero
  float reach_mm = 0.0f;  // the largest |p - p0| on the axis's travel (slew limit of the slope)
};

struct ThermalModel {
  uint8_t axis_count = 0;    // 1..kMaxModelAxes
  uint8_t channel_mask = 0;  // channels with a non-zero coefficient on any axis
  int16_t reference_cC[kMaxChannels] = {};
  // The temperatures the model was calibrated over, per channel (low <= high).
  int16_t calibrated_low_cC[kMaxChannels] = {};
  int16_t calibrated_high_cC[kMaxChannels] = {};
  AxisModel axis[kMaxModelAxes];
  float slew_um_s = 1.0f;    // fastest change of the correction anywhere on an axis, > 0
  uint32_t hold_ms = 60000;  // hold time after a channel fault before the fade-out
};

/// Bounds of a model's values (the image parser and ThermalCorrection check the same).
inline constexpr float kMaxThermalCoefficient = 1000.0f;  // |um/K| and |um/(K m)|
inline constexpr float kMaxSlew_um_s = 1000.0f;
inline constexpr uint32_t kMaxHold_ms = 3600000;  // an hour
inline constexpr float kMaxPosition_mm = 1.0e6f;  // |p0| and reach

/// kOk; kThermalBadAxisCount for axis_count outside 1..kMaxModelAxes; kThermalBadModel for a
/// coefficient above kMaxThermalCoefficient, not finite, or not zero on a channel outside
/// channel_mask or an axis beyond axis_count; a calibrated range with low > high; slew outside
/// (0, kMaxSlew_um_s]; hold above kMaxHold_ms; |p0| or reach above kMaxPosition_mm, reach < 0.
Status ValidateThermalModel(const ThermalModel& m);

/// What the board shows (object, status flag, `volcomp status`).
struct ThermalStatus {
  bool active = false;       // a model is configured
  bool holding = false;      // a used channel is in a fault: the correction is held
  bool fading = false;       // the hold time ran out: the correction fades to zero
  bool slewing = false;      // the applied correction lags the model (at the slew limit)
  uint8_t fault_mask = 0;    // used channels in a fault state
  uint8_t outside_mask = 0;  // used channels outside their calibrated range (taken at its edge)
};

class ThermalCorrection {
 public:
  /// Takes `model` (checked by ValidateThermalModel; nothing changes on an error) for an Update()
  /// every `period_ms` (1..1000; kInvalidArgument otherwise). The applied correction starts at zero
  /// and moves to the model at the slew limit.
  Status Configure(const ThermalModel& model, uint32_t period_ms);
  /// No model: the applied correction fades to zero at the last model's slew limit.
  void Clear();

  /// One period: evaluates the model from `channels` and moves the applied terms.
  void Update(const TemperatureChannels& channels);

  /// The model's error of axis `a` at the last Update() (before the slew limit), um and um/mm.
  float model_offset_um(uint8_t a) const { return model_offset_um_[a]; }
  float model_slope_um_per_mm(uint8_t a) const { return model_slope_um_mm_[a]; }
  /// The applied terms of axis `a`, um and um/mm.
  float applied_offset_um(uint8_t a) const { return offset_um_[a]; }
  float applied_slope_um_per_mm(uint8_t a) const { return slope_um_mm_[a]; }
  /// Where the applied slope term of axis `a` is zero, mm (the model's p0 once one was configured).
  float applied_p0_mm(uint8_t a) const { return p0_mm_[a]; }
  /// The applied correction of axis `a` at `p_mm`, um.
  float CorrectionAt_um(uint8_t a, float p_mm) const {
    return offset_um_[a] + slope_um_mm_[a] * (p_mm - p0_mm_[a]);
  }
  const ThermalStatus& status() const { return status_; }
  /// The channels the model in force uses (0 without one).
  uint8_t model_channels() const { return status_.active ? model_.channel_mask : 0; }

 private:
  // The model's offset and slope of every axis at the channels' temperatures.
  void Evaluate(const TemperatureChannels& channels);
  // Moves the applied terms toward (offset, slope) of each axis within the slew limit.
  void Slew(const float* offset_um, const float* slope_um_mm);

  ThermalModel model_;
  uint32_t period_ms_ = 100;
  uint32_t held_ms_ = 0;  // time in the hold so far
  ThermalStatus status_;
  float model_offset_um_[kMaxModelAxes] = {};
  float model_slope_um_mm_[kMaxModelAxes] = {};
  float offset_um_[kMaxModelAxes] = {};
  float slope_um_mm_[kMaxModelAxes] = {};
  float p0_mm_[kMaxModelAxes] = {};     // the applied slope's zero
  float reach_mm_[kMaxModelAxes] = {};  // the largest reach any model gave the axis
};

}  // namespace volcomp::thermal
