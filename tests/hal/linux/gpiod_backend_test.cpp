// The libgpiod backend's error path: a missing chip is named.
#include "volcomp/hal/linux/gpiod_backend.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::hal::linux_board {
namespace {

TEST(GpiodBackendTest, NamesTheMissingChip) {
  std::unique_ptr<GpioBackend> gpio = MakeGpiodBackend();
  if (!HaveLibgpiod()) {
    EXPECT_EQ(gpio, nullptr);
    GTEST_SKIP() << "built without libgpiod";
  }
  ASSERT_NE(gpio, nullptr);
  EXPECT_NE(gpio->Describe().find("libgpiod 1."), std::string::npos) << gpio->Describe();
  GpioConfig c;
  const Expected<GpioLineSpec> spec = ParseGpioLineSpec("volcomp-no-such-chip:3");
  ASSERT_TRUE(spec.ok());
  c.input[7] = *spec;
  const Expected<void> opened = gpio->Open(c);
  ASSERT_FALSE(opened.ok());
  const std::string why = opened.error().message;
  EXPECT_NE(why.find("estop"), std::string::npos) << why;
  EXPECT_NE(why.find("volcomp-no-such-chip"), std::string::npos) << why;
  // Nothing configured: nothing requested, every input reads inactive.
  EXPECT_TRUE(gpio->Open(GpioConfig()).ok());
  bool levels[kInputLineCount] = {true, true, true, true, true, true, true, true, true, true};
  EXPECT_TRUE(gpio->ReadInputs(levels).ok());
  for (bool l : levels) EXPECT_FALSE(l);
}

}  // namespace
}  // namespace volcomp::hal::linux_board
