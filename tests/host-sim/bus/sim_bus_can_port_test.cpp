// SimBusCanPort: the firmware's CanPort on a bus endpoint (transmit capacity, FIFO, validity).
#include "volcomp/sim/sim_bus_can_port.hpp"

#include <gtest/gtest.h>

#include "can_frames.hpp"

namespace volcomp::sim {
namespace {

CanFrame Frame(uint32_t id, std::vector<uint8_t> data = {}, bool ext = false, bool rtr = false) {
  return testing::Frame(id, ext, rtr, std::move(data));
}

TEST(CanIoSimBus, CanPortAdapter) {
  SimBus bus(1000000);
  SimBusCanPort board(bus.Attach("board"), /*tx_capacity=*/2);
  SimBusCanPort pc(bus.Attach("pc"));
  hal::CanPort& port = board;  // used through the firmware's interface
  EXPECT_TRUE(port.Send(Frame(0x701, {0x7F})).ok());
  EXPECT_TRUE(port.Send(Frame(0x181, {1})).ok());
  EXPECT_EQ(port.Send(Frame(0x182)).error(), Error::kFull);
  EXPECT_EQ(port.Send(Frame(0x800)).error(), Error::kInvalidArgument);
  bus.RunUntilIdle();
  CanFrame f;
  ASSERT_TRUE(static_cast<hal::CanPort&>(pc).Receive(&f));
  EXPECT_EQ(f.id, 0x701u);  // FIFO within the node
  ASSERT_TRUE(static_cast<hal::CanPort&>(pc).Receive(&f));
  EXPECT_EQ(f.id, 0x181u);
  EXPECT_FALSE(static_cast<hal::CanPort&>(pc).Receive(&f));
  EXPECT_TRUE(port.Send(Frame(0x182)).ok());
}

}  // namespace
}  // namespace volcomp::sim
