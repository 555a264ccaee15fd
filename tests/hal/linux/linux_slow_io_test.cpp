// LinuxSlowIo: software debounce, fail-safe stop inputs.
#include "volcomp/hal/linux/linux_slow_io.hpp"

#include <gtest/gtest.h>

#include "volcomp/hal/linux/fake_gpio.hpp"

namespace volcomp::hal::linux_board {
namespace {

TEST(LinuxSlowIoTest, DebouncesAndIsFailSafeForStopInputs) {
  FakeGpio gpio;
  ASSERT_TRUE(gpio.Open(GpioConfig()).ok());
  LinuxSlowIo::Options o;
  o.debounce_ms = 5;
  LinuxSlowIo io(&gpio, o);
  SlowIo& slow = io;
  gpio.SetInput(InputLine::kWriteEnable, true);
  io.Refresh(0);  // the first reading is taken as is
  EXPECT_TRUE(slow.Read(InputLine::kWriteEnable));
  // A home switch must be stable for 5 ms.
  gpio.SetInput(HomeLine(0), true);
  io.Refresh(1000000);
  EXPECT_FALSE(slow.Read(HomeLine(0)));
  EXPECT_TRUE(io.raw(HomeLine(0)));
  io.Refresh(5999999);
  EXPECT_FALSE(slow.Read(HomeLine(0)));
  io.Refresh(6000000);
  EXPECT_TRUE(slow.Read(HomeLine(0)));
  // A bounce restarts the timing.
  gpio.SetInput(HomeLine(0), false);
  io.Refresh(7000000);
  gpio.SetInput(HomeLine(0), true);
  io.Refresh(8000000);
  gpio.SetInput(HomeLine(0), false);
  io.Refresh(9000000);
  io.Refresh(13000000);
  EXPECT_TRUE(slow.Read(HomeLine(0)));
  io.Refresh(14000000);
  EXPECT_FALSE(slow.Read(HomeLine(0)));
  // E-stop and drive alarm: active at once, inactive only after the debounce time.
  gpio.SetInput(InputLine::kEStop, true);
  io.Refresh(20000000);
  EXPECT_TRUE(slow.Read(InputLine::kEStop));
  gpio.SetInput(InputLine::kEStop, false);
  io.Refresh(21000000);
  EXPECT_TRUE(slow.Read(InputLine::kEStop));
  io.Refresh(26000000);
  EXPECT_FALSE(slow.Read(InputLine::kEStop));
  gpio.SetInput(InputLine::kDriveAlarm, true);
  io.Refresh(27000000);
  EXPECT_TRUE(slow.Read(InputLine::kDriveAlarm));
  // Outputs are written through on change.
  slow.Write(OutputLine::kReady, true);
  EXPECT_TRUE(gpio.output(OutputLine::kReady));
  EXPECT_TRUE(io.output(OutputLine::kReady));
  EXPECT_EQ(io.errors(), 0u);
}

}  // namespace
}  // namespace volcomp::hal::linux_board
