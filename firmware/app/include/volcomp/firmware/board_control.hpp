// What the object dictionary may ask of the running board application (implemented by BoardApp).
// Requests that touch the data path are handed to the next control tick, never applied from the
// main loop directly.
#pragma once

#include <cstdint>

#include "volcomp/control/compensator.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/firmware/tick_io.hpp"

namespace volcomp::firmware {

class BoardControl {
 public:
  /// The activation sequence: prepares the parsed image `view` against the configuration in force,
  /// hands it to the tick (active from the next tick on) and marks it active (0x2103 / 0x2104).
  /// The image bytes must stay valid and unchanged while it is active. On error nothing changes.
  [[nodiscard]] Status ActivateTable(const table::TableView& view) { return DoActivateTable(view); }
  /// Drops the active table at the next tick (the correction ramps out).
  void RequestClearTable() { DoRequestClearTable(); }
  /// References the axes in `mask` (bit a = axis a) at the next tick.
  void RequestReference(uint8_t mask) { DoRequestReference(mask); }
  /// Enables or disables compensation from the bus (AND-ed with the enable input).
  void SetBusEnable(bool on) { DoSetBusEnable(on); }
  bool bus_enable() const { return DoBusEnable(); }
  /// The data path, for reading state (positions, corrections, counters).
  const ControlTick& control_tick() const { return DoControlTick(); }
  /// The output stage's counters (output positions, backlog).
  OutputStatus output_status() const { return DoOutputStatus(); }
  /// True while any axis moved within the last `ms` milliseconds.
  bool moving() const { return DoMoving(); }
  bool fault() const { return DoFault(); }
  /// Hardware write-enable input level.
  bool write_enable_input() const { return DoWriteEnableInput(); }
  uint32_t max_tick_cost_ns() const { return DoMaxTickCostNs(); }

 protected:
  ~BoardControl() = default;

 private:
  virtual Status DoActivateTable(const table::TableView& view) = 0;
  virtual void DoRequestClearTable() = 0;
  virtual void DoRequestReference(uint8_t mask) = 0;
  virtual void DoSetBusEnable(bool on) = 0;
  virtual bool DoBusEnable() const = 0;
  virtual const ControlTick& DoControlTick() const = 0;
  virtual OutputStatus DoOutputStatus() const = 0;
  virtual bool DoMoving() const = 0;
  virtual bool DoFault() const = 0;
  virtual bool DoWriteEnableInput() const = 0;
  virtual uint32_t DoMaxTickCostNs() const = 0;
};

}  // namespace volcomp::firmware
