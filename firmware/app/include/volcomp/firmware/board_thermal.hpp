// The thermal correction in the board's main loop (docs/thermal.md): the temperature channels as
// the settings in force configure them, the thermal model of the active table image, and, every
// kThermalPeriodMs, the channels' supervision, the model's update and the hand-over of its terms
// in steps to the compensation run (Compensator::PublishThermal()).
//
//   Start()      a board start: the channels from the settings (all restart), no model, zero
//                terms handed to the run.
//   SetModel()   the activation sequence (BoardPolicy::Activate()): once the table is published,
//                its model replaces the last (the applied correction moves to it at the slew
//                limit, never jumps). An image without a THERMAL section, or no table, fades the
//                applied correction out at the last model's slew limit. (ParseImage() and
//                CheckImageMatchesBoard() have checked the section against the axes: no more axes
//                than the board, no term on a rotary axis.)
//   Reading()    a channel's reading from its source (the CAN object's writes).
//   Poll()       every main-loop pass; does one period's work when one is due (first the new
//                readings of the board's own sensors, hal::TemperatureInputs), and returns the
//                events the owner reports (EMCY, status flag).
//
// A term that does not fit the run's bounds (thermal_term.hpp) is handed over saturated and
// flagged (saturated_axes(), a fault): never applied silently as something else.
// Main loop only: the compensation run reads only what PublishThermal() hands over.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/hal/temperature_inputs.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/thermal/temperature_channels.hpp"
#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::firmware {

/// The main loop's thermal period: channel supervision (staleness) and the model's update, 10 Hz.
inline constexpr uint32_t kThermalPeriodMs = 100;

/// What one Poll() saw: each onset and recovery once.
struct ThermalEvents {
  thermal::ChannelEvents channels;  // bit n: channel n faulted / recovered (or, for a channel the
                                    // settings leave unused, the model in force started / stopped
                                    // using it)
  uint8_t saturated = 0;            // bit a: axis a's terms started not to fit the run's bounds
  uint8_t unsaturated = 0;          // bit a: they fit again
  bool any() const {
    return (channels.faulted | channels.recovered | saturated | unsaturated) != 0;
  }
};

class BoardThermal {
 public:
  /// Configures the channels from `settings.temperature` (validated settings: a channel the
  /// channels refuse is left unused) at `now_ms`, drops the model (no fade: the run restarts at
  /// zero terms) and hands zero terms to `compensator`, which Poll() publishes to from now on.
  void Start(const BoardSettings& settings, Compensator* compensator, uint32_t now_ms);

  /// The model of the image just activated: its THERMAL section, or none.
  void SetModel(const table::TableView& image);
  /// No table: the applied correction fades out at the last model's slew limit.
  void ClearModel();

  /// A reading of channel `ch` (TemperatureChannels::Reading()).
  Status Reading(uint8_t ch, int16_t value_cC, uint32_t now_ms) {
    return channels_.Reading(ch, value_cC, now_ms);
  }

  /// The main loop's pass at `now_ms`: when kThermalPeriodMs have passed since the last period,
  /// takes the new readings of the channels whose source is a board sensor from `sensors` (none:
  /// a board without them, such channels go stale), supervises the channels, updates the model,
  /// converts and publishes the terms. A loop that falls behind by more than a period does one
  /// period's work (the correction then moves more slowly than its slew limit, never faster).
  ThermalEvents Poll(uint32_t now_ms, hal::TemperatureInputs* sensors = nullptr);

  const thermal::TemperatureChannels& channels() const { return channels_; }
  const thermal::ThermalCorrection& correction() const { return correction_; }
  /// The terms handed over last, per board axis.
  const thermal::ThermalTermSteps& term(uint8_t a) const { return terms_[a]; }
  /// Bit a: axis a's terms are saturated (the model asks for more than the run can apply).
  uint8_t saturated_axes() const { return saturated_; }
  /// Channels in a fault: configured ones in a fault state, and channels the model in force uses
  /// that the settings leave unused (a model the board cannot apply: it holds, then fades).
  uint8_t channel_fault_mask() const { return channels_.fault_mask() | unconfigured_; }
  /// What the status flag shows: a channel in a fault (above) or a term saturated.
  bool fault() const { return channel_fault_mask() != 0 || saturated_ != 0; }

 private:
  thermal::TemperatureChannels channels_;
  thermal::ThermalCorrection correction_;
  Compensator* compensator_ = nullptr;
  uint8_t axis_count_ = 0;
  uint32_t resolution_pm_[table::kMaxAxes] = {};  // 0 on rotary axes: no thermal term
  thermal::ThermalTermSteps terms_[table::kMaxAxes];
  uint8_t saturated_ = 0;
  uint8_t unconfigured_ = 0;  // channels the model uses that are unused
  uint32_t last_period_ms_ = 0;
};

}  // namespace volcomp::firmware
