// FakeGpio: the state file drives the inputs and receives the outputs.
#include "volcomp/hal/linux/fake_gpio.hpp"

#include <gtest/gtest.h>

#include <string>

#include "file_contents.hpp"
#include "temp_paths.hpp"

namespace volcomp::hal::linux_board {
namespace {

using volcomp::testing::ReadText;
using volcomp::testing::ScratchDir;
using volcomp::testing::WriteText;

TEST(FakeGpioTest, StateFileDrivesInputsAndReceivesOutputs) {
  ScratchDir dir("hal_test");
  const std::string path = dir / "gpio";
  WriteText(path, "# bench\nestop=1\nhome1 = 1   # switch pressed\nwrite_enable=0\n");
  FakeGpio gpio(path);
  ASSERT_TRUE(gpio.Open(GpioConfig()).ok());
  gpio.SetInput(InputLine::kEnable, true);       // not named in the file: the memory value counts
  gpio.SetInput(InputLine::kWriteEnable, true);  // named in the file: the file wins
  bool levels[kInputLineCount];
  ASSERT_TRUE(gpio.ReadInputs(levels).ok());
  EXPECT_TRUE(levels[static_cast<int>(InputLine::kEStop)]);
  EXPECT_TRUE(levels[static_cast<int>(HomeLine(1))]);
  EXPECT_FALSE(levels[static_cast<int>(HomeLine(0))]);
  EXPECT_TRUE(levels[static_cast<int>(InputLine::kEnable)]);
  EXPECT_FALSE(levels[static_cast<int>(InputLine::kWriteEnable)]);
  // The file is re-read only when it changes.
  const uint32_t reads = gpio.file_reads();
  ASSERT_TRUE(gpio.ReadInputs(levels).ok());
  EXPECT_EQ(gpio.file_reads(), reads);
  WriteText(path, "estop=0\n");  // another size: seen even within the same mtime tick
  ASSERT_TRUE(gpio.ReadInputs(levels).ok());
  EXPECT_FALSE(levels[static_cast<int>(InputLine::kEStop)]);
  EXPECT_FALSE(levels[static_cast<int>(HomeLine(1))]);
  // Outputs go to PATH.out.
  ASSERT_TRUE(gpio.WriteOutput(OutputLine::kFault, true).ok());
  EXPECT_EQ(ReadText(path + ".out"), "ready=0\ncompensating=0\nfault=1\n");
  EXPECT_TRUE(gpio.output(OutputLine::kFault));
  // A malformed line is reported with its number.
  WriteText(path, "estop=1\nestpo=1\n");
  const Expected<void> read = gpio.ReadInputs(levels);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find(":2:"), std::string::npos) << read.error().message;
}

}  // namespace
}  // namespace volcomp::hal::linux_board
