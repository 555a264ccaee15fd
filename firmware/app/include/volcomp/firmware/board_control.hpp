// What only the board application's tick knows, for the dictionary's diagnostics (implemented by
// BoardApp<Io>, whose output stage is its template parameter). Reads, from the main loop; the
// requests and rules of the bus are BoardPolicy's (board_policy.hpp).
#pragma once

#include <cstdint>

#include "volcomp/firmware/tick_io.hpp"

namespace volcomp::firmware {

class BoardControl {
 public:
  /// The output stage's counters (output positions, backlog).
  OutputStatus output_status() const { return DoOutputStatus(); }
  /// The longest timed tick so far, ns (0 while only untimed ticks run).
  uint32_t max_tick_cost_ns() const { return DoMaxTickCostNs(); }

 protected:
  ~BoardControl() = default;

 private:
  virtual OutputStatus DoOutputStatus() const = 0;
  virtual uint32_t DoMaxTickCostNs() const = 0;
};

}  // namespace volcomp::firmware
