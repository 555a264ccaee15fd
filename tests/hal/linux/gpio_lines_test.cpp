// Line specs of the slow lines: parsing and formatting.
#include "volcomp/hal/linux/gpio_lines.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::hal::linux_board {
namespace {

TEST(GpioLineSpecTest, ParsesAndFormats) {
  GpioLineSpec s;
  auto parse = [&s](const std::string& text) {
    const Expected<GpioLineSpec> r = ParseGpioLineSpec(text);
    if (r.ok()) s = *r;
    return r.ok();
  };
  ASSERT_TRUE(parse("gpiochip0:17 active-low pull-up"));
  EXPECT_TRUE(s.used);
  EXPECT_EQ(s.chip, "gpiochip0");
  EXPECT_EQ(s.offset, 17u);
  EXPECT_TRUE(s.active_low);
  EXPECT_EQ(s.bias, Bias::kPullUp);
  EXPECT_EQ(FormatGpioLineSpec(s), "gpiochip0:17 active-low pull-up");
  ASSERT_TRUE(parse("/dev/gpiochip1:3"));
  EXPECT_EQ(s.chip, "/dev/gpiochip1");
  EXPECT_EQ(s.offset, 3u);
  EXPECT_FALSE(s.active_low);
  ASSERT_TRUE(parse("ESTOP_IN bias-disable"));
  EXPECT_TRUE(s.chip.empty());
  EXPECT_EQ(s.line_name, "ESTOP_IN");
  EXPECT_EQ(s.bias, Bias::kDisable);
  EXPECT_FALSE(parse("gpiochip0:x"));
  EXPECT_FALSE(parse(":4"));
  EXPECT_FALSE(parse("gpiochip0:4 open-drain"));
  EXPECT_FALSE(parse("gpiochip0:4 pull-up pull-down"));
  EXPECT_FALSE(parse("   "));
  InputLine in;
  EXPECT_TRUE(InputLineFromName("drive_alarm", &in));
  EXPECT_EQ(in, InputLine::kDriveAlarm);
  EXPECT_TRUE(InputLineFromName("home3", &in));
  EXPECT_EQ(in, HomeLine(3));
  EXPECT_FALSE(InputLineFromName("ready", &in));
  OutputLine out;
  EXPECT_TRUE(OutputLineFromName("compensating", &out));
  EXPECT_EQ(out, OutputLine::kCompensating);
}

}  // namespace
}  // namespace volcomp::hal::linux_board
