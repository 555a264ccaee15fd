// The board of volcomp-fw-linux without its event loop: the devices a configuration names (flash
// files, GPIO backend and debounced slow lines, the timerfd tick, the monotonic clock, the
// temperature files and their reader threads) and the
// GatewayApp on them, on CAN ports the caller opens (SocketCAN in the process, mock ports in
// tests). The board application owns the configuration in force: it sets the tick timer's rate at
// start and at every NMT reset node; OnTimer() runs the ticks the timer delivered.
//
//   Open()       opens the devices and starts the board (stored settings override the file's).
//   OnTimer()    when fd() of tick_timer() is readable: the due ticks (at most kMaxCatchUpTicks;
//                the rest are counted as skipped), the slow lines every poll_ms, one main-loop
//                pass. A (re)start of the tick timer (a node reset) is reported through
//                Options::log with the configuration in force, and so are the temperature
//                files' failures and recoveries (each once).
//   Shutdown()   outputs inactive, temperature readers stopped, file writes flushed.
//
// Thread-safety: one thread (the event loop).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "volcomp/firmware/gateway_app.hpp"
#include "volcomp/hal/can.hpp"
#include "volcomp/hal/linux/file_flash.hpp"
#include "volcomp/hal/linux/gpio_lines.hpp"
#include "volcomp/hal/linux/linux_slow_io.hpp"
#include "volcomp/hal/linux/monotonic_clock.hpp"
#include "volcomp/hal/linux/tick_timer.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/linux_board/config_file.hpp"
#include "volcomp/linux_board/temperature_files.hpp"

namespace volcomp::linux_board {

struct TickCounters {
  uint64_t ticks = 0;    // ticks run
  uint64_t late = 0;     // expirations beyond the first per OnTimer() (the loop was late)
  uint64_t skipped = 0;  // expirations not run (more than kMaxCatchUpTicks at once)
  uint64_t max_tick_ns = 0;
};

class LinuxBoard {
 public:
  static constexpr uint64_t kMaxCatchUpTicks = 10;

  struct Options {
    /// Receives one line per event worth a log line (a node reset: the configuration in force
    /// and any refusal; a file write error at shutdown). Default: stderr, prefixed
    /// "volcomp-fw-linux: ".
    std::function<void(const std::string& line)> log;
    /// What the CAN port found about the bit rate (appended to DescribeConfigInForce()).
    std::function<std::string()> bus_detail;
  };

  LinuxBoard(const LinuxBoardConfig& config, const Options& options);
  explicit LinuxBoard(const LinuxBoardConfig& config) : LinuxBoard(config, Options()) {}
  ~LinuxBoard();
  LinuxBoard(const LinuxBoard&) = delete;
  LinuxBoard& operator=(const LinuxBoard&) = delete;

  /// Opens the devices and starts the board on `controller` (required) and `drives` (null: a
  /// plain node). A failure names the device (or the configuration) and the cause.
  Expected<void> Open(hal::CanPort* controller, hal::CanPort* drives);
  void OnTimer();
  void Shutdown();

  firmware::GatewayApp& app() { return *app_; }
  const firmware::GatewayApp& app() const { return *app_; }
  hal::linux_board::TickTimer& tick_timer() { return timer_; }
  hal::linux_board::FileFlash& tables() { return tables_; }
  hal::linux_board::LinuxSlowIo& io() { return *io_; }
  hal::linux_board::GpioBackend& gpio() { return *gpio_; }
  TemperatureFiles& temperature_files() { return *temperatures_; }
  const TickCounters& tick_counters() const { return ticks_; }
  /// "tick 1000 Hz (timer period 1000000 ns), bit rate 1000 kbit/s, node 0x10, 3 axes" plus the
  /// refusal of stored settings or the bit-rate mismatch when there is one, and bus_detail().
  std::string DescribeConfigInForce() const;

 private:
  void Log(const std::string& line) const;
  void LogTemperatureSources();

  LinuxBoardConfig config_;
  Options options_;
  hal::linux_board::MonotonicClock clock_;
  hal::linux_board::TickTimer timer_;
  hal::linux_board::FileFlash tables_;
  hal::linux_board::FileFlash settings_;
  bool have_settings_ = false;
  std::unique_ptr<hal::linux_board::GpioBackend> gpio_;
  std::unique_ptr<hal::linux_board::LinuxSlowIo> io_;
  std::unique_ptr<TemperatureFiles> temperatures_;
  std::unique_ptr<firmware::GatewayApp> app_;
  TickCounters ticks_;
  uint64_t timer_starts_seen_ = 0;
  uint64_t next_io_ns_ = 0;
};

}  // namespace volcomp::linux_board
