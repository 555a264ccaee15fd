// TickTimer: timerfd expirations, Stop() and a restart at a new rate.
#include "volcomp/hal/linux/tick_timer.hpp"

#include <gtest/gtest.h>
#include <sys/timerfd.h>
#include <unistd.h>

namespace volcomp::hal::linux_board {
namespace {

TEST(TickTimerTest, CountsExpirations) {
  TickTimer timer;
  hal::TickTimer& tick = timer;
  EXPECT_EQ(tick.SetRate(1000).error(), Error::kNotReady);  // not open
  ASSERT_TRUE(timer.Open().ok());
  EXPECT_GE(timer.fd(), 0);
  EXPECT_EQ(tick.SetRate(100000000).error(), Error::kConfigInvalid);  // a 10 ns period
  EXPECT_EQ(tick.Start().error(), Error::kNotReady);                  // no rate yet
  ASSERT_TRUE(tick.SetRate(1000).ok());                               // 1 ms
  EXPECT_EQ(timer.period_ns(), 1000000u);
  ASSERT_TRUE(tick.Start().ok());
  EXPECT_EQ(tick.SetRate(2000).error(), Error::kBusy);  // the rate changes only while stopped
  usleep(5000);
  EXPECT_GE(timer.Take(), 1u);  // at least one period passed
  timer.Close();
  EXPECT_EQ(timer.Take(), 0u);
}

TEST(TickTimerTest, StopDiscardsAndARestartRunsAtTheNewRate) {
  TickTimer timer;
  hal::TickTimer& tick = timer;
  ASSERT_TRUE(timer.Open().ok());
  const int fd = timer.fd();
  ASSERT_TRUE(tick.SetRate(10000).ok());
  ASSERT_TRUE(tick.Start().ok());
  usleep(3000);
  tick.Stop();
  EXPECT_EQ(timer.Take(), 0u);  // expirations before Stop() are gone
  usleep(2000);
  EXPECT_EQ(timer.Take(), 0u);  // stopped
  ASSERT_TRUE(tick.SetRate(2000).ok());
  ASSERT_TRUE(tick.Start().ok());
  EXPECT_EQ(timer.fd(), fd);  // the event loop keeps watching the same fd
  EXPECT_EQ(timer.starts(), 2u);
  // The kernel's own view of the armed period (independent of period_ns()).
  itimerspec spec{};
  ASSERT_EQ(timerfd_gettime(timer.fd(), &spec), 0);
  EXPECT_EQ(spec.it_interval.tv_sec, 0);
  EXPECT_EQ(spec.it_interval.tv_nsec, 500000);
}

}  // namespace
}  // namespace volcomp::hal::linux_board
