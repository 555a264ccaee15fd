// ShutdownSignal: SIGTERM arrives on the signalfd.
#include "volcomp/hal/linux/shutdown_signal.hpp"

#include <gtest/gtest.h>
#include <signal.h>

namespace volcomp::hal::linux_board {
namespace {

TEST(ShutdownSignalTest, SigtermArrivesOnTheFd) {
  ShutdownSignal sig;
  ASSERT_TRUE(sig.Open().ok());
  EXPECT_EQ(sig.Take(), 0);
  ASSERT_EQ(kill(getpid(), SIGTERM), 0);  // blocked: it stays pending for the signalfd
  EXPECT_EQ(sig.Take(), SIGTERM);
  EXPECT_EQ(sig.Take(), 0);
  sig.Close();
}

}  // namespace
}  // namespace volcomp::hal::linux_board
