// The real board application (firmware/app BoardApp) on the mock HAL, on a simulated CAN bus
// endpoint, in virtual time (ns): a control tick at the rate the firmware programmed into its
// tick timer (period 1e9 / rate ns, truncated, while the timer runs; a node reset may change it)
// and a main-loop pass every `poll_period_ns`; the endpoint at the bit rate the firmware set.
// Flash is in memory; with a flash directory it is loaded from its files at Start() and every
// operation is written through at once (write_through_flash.hpp), so killing the process is a
// real power loss. Thread-safety: none (one thread drives the board and its bus).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/sim/sim_bus.hpp"
#include "volcomp/sim/sim_bus_can_port.hpp"
#include "volcomp/sim/write_through_flash.hpp"

namespace volcomp::sim {

struct SimulatedBoardOptions {
  BoardSettings settings;                 // factory defaults (stored settings override)
  uint32_t table_flash_bytes = 1u << 20;  // two banks of 512 KiB
  uint32_t settings_flash_bytes = 8192;
  uint32_t flash_sector_bytes = 2048;        // STM32G4 page size
  uint64_t poll_period_ns = 100000;          // main loop every 100 us
  bool write_enable_input = false;           // hardware write-enable jumper
  bool enable_input = true;                  // compensation enable input from the CNC
  std::string flash_dir;                     // flash files, written through, when not empty
  std::vector<uint8_t> initial_table_flash;  // start with this table flash content (power cycle)
};

class SimulatedBoard {
 public:
  using TickIo = firmware::StepDirIo<hal::mock::MockStepIo>;
  using App = firmware::BoardApp<TickIo>;

  SimulatedBoard(SimBus& bus, const SimulatedBoardOptions& options);
  ~SimulatedBoard();

  /// Starts the firmware (opens and loads the flash files first when configured). Fails with
  /// kIoError naming a flash file that cannot be opened or written, or with the firmware's error
  /// ("the firmware did not start: ...").
  Outcome Start();
  /// Runs ticks and main-loop passes up to virtual time `t_ns` (the bus must be advanced in step:
  /// see StepTo() and AdvanceInEventOrder() below).
  void AdvanceTo(uint64_t t_ns);
  /// Virtual time of the next tick or poll.
  uint64_t NextEventTime() const;
  /// Writes the whole flash images to `flash_dir` (no-op without one; every operation is already
  /// written through).
  void SaveFlash() const;

  App& app() { return *app_; }
  hal::mock::MockStepIo& step_io() { return *step_io_; }
  /// The step/dir output stage (output positions, backlog).
  const StepOutput& output() const { return tick_io_->output(); }
  hal::mock::MockSlowIo& io() { return io_; }
  const hal::mock::MockTickTimer& tick_timer() const { return tick_timer_; }
  /// The tick period the board runs at now (0 while the tick timer is stopped).
  uint64_t tick_period_ns() const { return tick_timer_.running() ? tick_ns_ : 0; }
  /// The table flash (fault injection, e.g. InjectPowerLossAfter; its raw() content).
  hal::mock::MockFlash& table_flash() { return table_flash_; }
  Endpoint& endpoint() { return endpoint_; }
  uint64_t now_ns() const { return now_ns_; }

 private:
  Outcome OpenFlashFiles();
  void LoadFlash();
  // Follows the tick timer after the firmware ran: a (re)start schedules the next tick.
  void FollowTickTimer();

  SimulatedBoardOptions options_;
  Endpoint& endpoint_;
  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockFlash table_flash_;
  hal::mock::MockFlash settings_flash_;
  std::unique_ptr<WriteThroughFlash> table_file_;  // with a flash directory
  std::unique_ptr<WriteThroughFlash> settings_file_;
  SimBusCanPort can_;
  hal::mock::MockTickTimer tick_timer_;
  uint32_t timer_starts_seen_ = 0;
  std::unique_ptr<hal::mock::MockStepIo> step_io_;
  std::unique_ptr<TickIo> tick_io_;
  std::unique_ptr<App> app_;
  uint64_t now_ns_ = 0;
  uint64_t tick_ns_ = 0;
  uint64_t next_tick_ns_ = UINT64_MAX;  // no tick while the timer is stopped
  uint64_t next_poll_ns_ = 0;
};

/// The earlier of the board's next tick or poll and the bus's next event.
uint64_t NextEventTime(const SimBus& bus, const SimulatedBoard& board);

/// One step of the co-simulation: the bus to `t_ns` (frames ending by then are delivered), then
/// the board's ticks and polls up to `t_ns`. A caller that acts between events (an SDO client, a
/// fault injector) calls it with t_ns = NextEventTime(bus, board) (or an earlier limit) and acts
/// after each step.
void StepTo(SimBus& bus, SimulatedBoard& board, uint64_t t_ns);

/// Runs the bus and the board to `t_ns` with every event of either in time order.
void AdvanceInEventOrder(SimBus& bus, SimulatedBoard& board, uint64_t t_ns);

}  // namespace volcomp::sim
