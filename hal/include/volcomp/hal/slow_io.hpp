// Slow digital lines (switches, enables, status outputs): read and written from the main loop,
// never from the tick. NVI interface; implementations: mock (tests, simulator), libgpiod (Linux
// board), GPIO registers (MCU).
#pragma once

#include <cstdint>

namespace volcomp::hal {

enum class InputLine : uint8_t {
  kHome0 = 0,        // home (reference) switch of axis 0; kHome0 + a for axis a (a < 6)
  kEnable = 6,       // compensation enable from the CNC (active high)
  kEStop = 7,        // emergency stop chain open (active high = stopped)
  kDriveAlarm = 8,   // any drive reports an alarm (active high)
  kWriteEnable = 9,  // write-enable key/jumper (active high = tables and settings writable)
  kCount = 10,
};

enum class OutputLine : uint8_t {
  kReady = 0,         // firmware running, configuration valid
  kCompensating = 1,  // correction engaged (enabled, referenced, table active)
  kFault = 2,         // a fault forced pass-through
  kCount = 3,
};

inline InputLine HomeLine(uint8_t axis) { return static_cast<InputLine>(axis); }

class SlowIo {
 public:
  bool Read(InputLine line) { return DoRead(line); }
  void Write(OutputLine line, bool level) { DoWrite(line, level); }

 protected:
  ~SlowIo() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual bool DoRead(InputLine line) = 0;
  virtual void DoWrite(OutputLine line, bool level) = 0;
};

}  // namespace volcomp::hal
