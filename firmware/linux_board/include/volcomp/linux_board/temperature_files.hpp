// The Linux board's temperature sensors (docs/thermal.md "Board-local sensors", docs/linux-board.md
// [sensors]): one sysfs file per temperature channel whose source is a Linux file, read by a
// thread of its own at the configured period and handed to the board as readings
// (hal::TemperatureInputs: BoardThermal takes them every 100 ms).
//
// Formats (ParseTemperatureText):
//   * one integer in millidegrees Celsius, e.g. "23125\n" or "-1250": hwmon temp*_input
//     (/sys/class/hwmon/hwmonN/tempM_input) and the w1_therm driver's temperature file
//     (/sys/bus/w1/devices/28-XXXXXXXXXXXX/temperature);
//   * w1_therm's w1_slave: two lines, the first ending in "crc=XX YES" (NO: a failed CRC, no
//     reading), the second ending in "t=MILLIDEGREES".
// Millidegrees are rounded to centi-degrees (half away from zero).
//
// A read that fails (the file missing, EIO from the sensor's bus, a CRC failure, text that is not
// a temperature, a value outside +-327.67 C) is a reading of thermal::kNoReading_cC, so the channel
// goes out of range at once rather than holding a value that looks current; the failure is named
// once in the log (TakeLog(): the file, the key, the cause) and its end once again ("reading
// again").
//
// Threads: each configured file has a reader thread (a read can block: a DS18B20 converts for
// 750 ms when its file is read, an I2C sensor waits for its bus), so the event loop never touches
// the files: it only takes the last result under a mutex (Take(), TakeLog()). A reader sleeps
// until `period_ms` after the start of its last read; Stop() wakes the sleepers and joins (a read
// in progress is waited for). The readers have 64 KB stacks (what mlockall locks of them, not the
// default 8 MB) and normal scheduling (they start before the event loop takes SCHED_FIFO).
#pragma once

#include <pthread.h>

#include <array>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "volcomp/hal/temperature_inputs.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp::linux_board {

/// The file's text as a temperature in centi-degrees C, or what is wrong with it (the message
/// quotes the text).
Expected<int16_t> ParseTemperatureText(const std::string& text);

/// Reads a file's text (up to 4 KB): its content, or an error naming the file and errno's text.
Expected<std::string> ReadSmallFile(const std::string& path);

class TemperatureFiles final : public hal::TemperatureInputs {
 public:
  /// paths[n]: the file of temperature channel n (empty: none). period_ms: 100..60000.
  TemperatureFiles(const std::array<std::string, thermal::kMaxChannels>& paths, uint32_t period_ms);
  ~TemperatureFiles();
  TemperatureFiles(const TemperatureFiles&) = delete;
  TemperatureFiles& operator=(const TemperatureFiles&) = delete;

  /// Starts a reader thread per configured file (none when no file is configured).
  void Start();
  /// Stops and joins the readers.
  void Stop();
  /// Reads channel n's file once and publishes the result (what a reader does each period; tests
  /// call it without threads).
  void ReadOnce(uint8_t channel);

  /// Log lines since the last call (failures and recoveries, each once).
  std::vector<std::string> TakeLog();

 private:
  struct Slot {
    std::string path;
    int16_t value_cC = thermal::kNoReading_cC;
    uint32_t published = 0;  // results published
    uint32_t taken = 0;      // results taken
    std::string failure;     // the standing failure ("" when reading)
  };
  bool DoTake(uint8_t channel, thermal::ChannelSource source, int16_t* value_cC) override;
  void Run(uint8_t channel);
  static void* ThreadMain(void* arg);

  uint32_t period_ms_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::array<Slot, thermal::kMaxChannels> slot_;
  std::vector<std::string> log_;
  struct Reader {
    TemperatureFiles* self;
    uint8_t channel;
  };
  std::array<Reader, thermal::kMaxChannels> reader_;
  std::vector<pthread_t> threads_;
};

}  // namespace volcomp::linux_board
