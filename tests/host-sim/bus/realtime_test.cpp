// RealtimeClock and RunRealtime: virtual bus time paced by the wall clock.
#include "volcomp/sim/realtime.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "can_frames.hpp"

namespace volcomp::sim {
namespace {

CanFrame Frame(uint32_t id, std::vector<uint8_t> data = {}, bool ext = false, bool rtr = false) {
  return testing::Frame(id, ext, rtr, std::move(data));
}

TEST(CanIoSimBus, RealtimePacing) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  Endpoint& b = bus.Attach("b");
  uint64_t bits = 0;
  for (int i = 0; i < 20; ++i) {
    const CanFrame f = Frame(0x100 + i, {1, 2, 3, 4, 5, 6, 7, 8});
    bits += CanFrameBits(f);
    a.Send(f);
  }
  const uint64_t busy_ns = bits * 1000;  // ~2.5 ms
  const RealtimeClock clock;
  const auto t0 = std::chrono::steady_clock::now();
  int waits = 0;
  const Outcome ran = RunRealtime(bus, clock, busy_ns, [&](std::chrono::microseconds timeout) {
    ++waits;
    std::this_thread::sleep_for(timeout);
    return Outcome::Ok();
  });
  ASSERT_TRUE(ran.ok()) << ran.error().message;
  const auto wall = std::chrono::steady_clock::now() - t0;
  EXPECT_GE(wall, std::chrono::nanoseconds(busy_ns));
  EXPECT_LT(wall, std::chrono::milliseconds(200));
  EXPECT_EQ(b.rx_pending(), 20u);
  EXPECT_GT(waits, 0);
  const RealtimeClock fast(1000, 4.0);
  EXPECT_GE(fast.Now(), 1000u);
  EXPECT_EQ(fast.Until(0), std::chrono::microseconds(0));
}

// A wait that fails (the link went away) ends the run with its failure.
TEST(CanIoSimBus, RealtimeRunStopsAtTheFirstFailedWait) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  bus.Attach("b");
  for (int i = 0; i < 20; ++i) a.Send(Frame(0x100 + i, {1, 2, 3, 4, 5, 6, 7, 8}));
  const RealtimeClock clock;
  int waits = 0;
  const Outcome ran =
      RunRealtime(bus, clock, clock.Now() + 1000000000, [&](std::chrono::microseconds) -> Outcome {
        if (++waits == 3) return Fail(Error::kCommunication, "link closed");
        return Outcome::Ok();
      });
  ASSERT_FALSE(ran.ok());
  EXPECT_EQ(ran.error().code, Error::kCommunication);
  EXPECT_EQ(ran.error().message, "link closed");
  EXPECT_EQ(waits, 3);
}

}  // namespace
}  // namespace volcomp::sim
