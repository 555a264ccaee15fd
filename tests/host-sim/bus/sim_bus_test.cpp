// SimBus: arbitration, frame timing, delivery, fault hooks, an endpoint at another bit rate.
#include "volcomp/sim/sim_bus.hpp"

#include <gtest/gtest.h>

#include "can_frames.hpp"
#include "volcomp/sim/sim_bus_can_port.hpp"

namespace volcomp::sim {
namespace {

CanFrame Frame(uint32_t id, std::vector<uint8_t> data = {}, bool ext = false, bool rtr = false) {
  return testing::Frame(id, ext, rtr, std::move(data));
}

std::vector<CanFrame> Drain(Endpoint& ep) {
  std::vector<CanFrame> out;
  CanFrame f;
  while (ep.Receive(&f)) out.push_back(f);
  return out;
}

TEST(CanIoSimBus, OneFrameTiming) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  Endpoint& b = bus.Attach("b");
  const CanFrame f = Frame(0x123, {1, 2, 3, 4, 5, 6, 7, 8});
  const uint32_t bits = CanFrameBits(f);
  std::vector<FrameRecord> records;
  bus.SetMonitor([&](const FrameRecord& r) { records.push_back(r); });
  uint64_t rx_time = 0;
  b.SetReceiveCallback([&](const CanFrame& got, uint64_t t) {
    EXPECT_EQ(got, f);
    rx_time = t;
  });
  EXPECT_FALSE(bus.NextEventTime());
  ASSERT_TRUE(a.Send(f));
  EXPECT_EQ(bus.NextEventTime(), 0u);
  bus.RunUntil(0);  // starts the frame
  EXPECT_EQ(bus.NextEventTime(), (bits - 3) * 1000u);
  bus.RunUntil(1000000);
  EXPECT_EQ(rx_time, (bits - 3) * 1000u);  // at the end of EOF
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].idle_ns, bits * 1000u);  // after the intermission
  EXPECT_EQ(records[0].bits, bits);
  EXPECT_EQ(bus.stats().frames, 1u);
  EXPECT_EQ(bus.stats().bits, bits);
  EXPECT_EQ(bus.stats().busy_ns, bits * 1000u);
  EXPECT_EQ(bus.now(), 1000000u);
  EXPECT_EQ(a.stats().sent, 1u);
  EXPECT_EQ(b.stats().received, 1u);
  EXPECT_EQ(a.rx_pending(), 0u);  // the sender does not receive its own frame
}

TEST(CanIoSimBus, LowerIdWinsAndTimesAdd) {
  for (uint32_t bitrate : {1000000u, 500000u, 125000u}) {
    SimBus bus(bitrate);
    Endpoint& a = bus.Attach("a");
    Endpoint& b = bus.Attach("b");
    Endpoint& c = bus.Attach("c");
    const CanFrame fa = Frame(0x200, {0xAA, 0x55});
    const CanFrame fb = Frame(0x100, {0x01});
    a.Send(fa);
    b.Send(fb);
    const uint64_t end = bus.RunUntilIdle();
    const auto got = Drain(c);
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0], fb);
    EXPECT_EQ(got[1], fa);
    const uint64_t bit_ns = 1000000000u / bitrate;
    EXPECT_EQ(end, (CanFrameBits(fa) + CanFrameBits(fb)) * bit_ns);
    EXPECT_EQ(bus.stats().busy_ns, end);
    EXPECT_TRUE(bus.idle());
  }
}

TEST(CanIoSimBus, ArbitrationField) {
  // Standard before extended with the same base id; data before remote; plain id order.
  EXPECT_LT(ArbitrationKey(Frame(0x100)), ArbitrationKey(Frame(0x100 << 18, {}, true)));
  EXPECT_LT(ArbitrationKey(Frame(0x100)), ArbitrationKey(Frame(0x100, {}, false, true)));
  EXPECT_LT(ArbitrationKey(Frame(0x0FF << 18 | 0x3FFFF, {}, true)), ArbitrationKey(Frame(0x100)));
  EXPECT_LT(ArbitrationKey(Frame(5, {}, true)), ArbitrationKey(Frame(6, {}, true)));
  EXPECT_LT(ArbitrationKey(Frame(0x100 << 18, {}, true, true)),
            ArbitrationKey(Frame(0x101 << 18, {}, true, false)));
}

TEST(CanIoSimBus, QueuedDuringATransmissionWaitsForArbitration) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  Endpoint& b = bus.Attach("b");
  Endpoint& mon = bus.Attach("monitor");
  a.Send(Frame(0x300, {1}));
  bus.RunUntil(10000);  // 0x300 is on the wire
  a.Send(Frame(0x200));
  b.Send(Frame(0x100));  // queued later but lower: wins the next arbitration
  bus.RunUntilIdle();
  const auto got = Drain(mon);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].id, 0x300u);
  EXPECT_EQ(got[1].id, 0x100u);
  EXPECT_EQ(got[2].id, 0x200u);
}

TEST(CanIoSimBus, EachEndpointKeepsItsOrder) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  Endpoint& mon = bus.Attach("monitor");
  a.Send(Frame(0x300));
  a.Send(Frame(0x100));  // a FIFO: no overtaking within one node
  bus.RunUntilIdle();
  const auto got = Drain(mon);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].id, 0x300u);
  EXPECT_EQ(got[1].id, 0x100u);
}

TEST(CanIoSimBus, ResponderAnswersAfterTheIntermission) {
  SimBus bus(1000000);
  Endpoint& client = bus.Attach("client");
  Endpoint& server = bus.Attach("server");
  server.SetReceiveCallback([&](const CanFrame& f, uint64_t) {
    server.Send(Frame(0x580 + (f.id - 0x600), {0x60, 0, 0, 0, 0, 0, 0, 0}));
  });
  std::vector<FrameRecord> records;
  bus.SetMonitor([&](const FrameRecord& r) { records.push_back(r); });
  const CanFrame req = Frame(0x601, {0x40, 0, 0x10, 0, 0, 0, 0, 0});
  client.Send(req);
  bus.RunUntilIdle();
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[1].start_ns, records[0].idle_ns);  // queued at EOF, starts after IFS
  EXPECT_EQ(Drain(client).size(), 1u);
}

TEST(CanIoSimBus, TimeNeverGoesBackwards) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  bus.Attach("b");
  bus.RunUntil(5000);
  bus.RunUntil(100);
  EXPECT_EQ(bus.now(), 5000u);
  a.Send(Frame(0x1));
  EXPECT_EQ(bus.NextEventTime(), 5000u);
  EXPECT_FALSE(a.Send(Frame(0x800)));  // invalid frames are refused
}

TEST(CanIoSimBus, ThroughputInVirtualTime) {
  // The in-process benchmark shape: 10,000 8-byte frames back to back at 1 Mbit/s.
  SimBus bus(1000000);
  Endpoint& tx = bus.Attach("tx");
  Endpoint& rx = bus.Attach("rx");
  uint64_t bits = 0;
  for (uint32_t i = 0; i < 10000; ++i) {
    const CanFrame f = Frame(0x600 + (i % 64), {uint8_t(i), uint8_t(i >> 8), 0, 0, 0, 0, 0, 0});
    bits += CanFrameBits(f);
    tx.Send(f);
  }
  const uint64_t end = bus.RunUntilIdle();
  EXPECT_EQ(end, bits * 1000u);
  EXPECT_EQ(rx.rx_pending(), 10000u);
  EXPECT_EQ(bus.stats().frames, 10000u);
  EXPECT_EQ(bus.stats().bits, bits);
  const double fps = 10000.0 / (static_cast<double>(end) * 1e-9);
  EXPECT_GT(fps, 7407.0);  // 135-bit worst case
  EXPECT_LT(fps, 9010.0);  // 111-bit best case
}

TEST(CanIoSimBus, FaultsDropDuplicateCorruptDestroy) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  Endpoint& b = bus.Attach("b");
  CanFrame corrupted = Frame(0x10, {0xFF});
  bus.SetFaultHook([&](const CanFrame& f, const Endpoint& sender) {
    EXPECT_EQ(sender.name(), "a");
    FaultDecision d;
    if (f.id == 0x11) d.action = FaultAction::kDrop;
    if (f.id == 0x12) d.action = FaultAction::kDuplicate;
    if (f.id == 0x10) {
      d.action = FaultAction::kCorrupt;
      d.corrupted = corrupted;
    }
    return d;
  });
  const CanFrame f10 = Frame(0x10, {0x01}), f11 = Frame(0x11), f12 = Frame(0x12, {7});
  a.Send(f10);
  a.Send(f11);
  a.Send(f12);
  const uint64_t end = bus.RunUntilIdle();
  const auto got = Drain(b);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], corrupted);
  EXPECT_EQ(got[1], f12);
  EXPECT_EQ(got[2], f12);
  EXPECT_EQ(end, (CanFrameBits(f10) + CanFrameBits(f11) + 2 * CanFrameBits(f12)) * 1000u);
  EXPECT_EQ(bus.stats().dropped, 1u);
  EXPECT_EQ(bus.stats().duplicated, 1u);
  EXPECT_EQ(bus.stats().corrupted, 1u);
  EXPECT_EQ(a.stats().sent, 3u);

  // Destroyed once: an error frame, then the automatic retransmission gets through.
  int destroyed = 0;
  bus.SetFaultHook([&](const CanFrame&, const Endpoint&) {
    FaultDecision d;
    if (destroyed++ == 0) d.action = FaultAction::kDestroy;
    return d;
  });
  const uint64_t t0 = bus.now();
  const CanFrame f = Frame(0x20, {1, 2, 3});
  a.Send(f);
  const uint64_t t1 = bus.RunUntilIdle();
  EXPECT_EQ(t1 - t0, (CanFrameBits(f) + 5 + CanFrameBits(f)) * 1000u);
  ASSERT_EQ(Drain(b), std::vector<CanFrame>{f});
  EXPECT_EQ(bus.stats().destroyed, 1u);
}

TEST(CanIoSimBus, RandomFaultsAreDeterministic) {
  auto run = [](uint64_t seed) {
    SimBus bus(1000000);
    Endpoint& a = bus.Attach("a");
    Endpoint& b = bus.Attach("b");
    RandomFaultRates rates;
    rates.drop = 0.1;
    rates.duplicate = 0.05;
    rates.corrupt = 0.05;
    rates.destroy = 0.05;
    bus.SetFaultHook(RandomFaults(seed, rates, [](const CanFrame& f) { return f.id >= 0x600; }));
    for (uint32_t i = 0; i < 2000; ++i) a.Send(Frame(i % 2 ? 0x601 : 0x181, {uint8_t(i)}));
    bus.RunUntilIdle();
    return std::make_pair(bus.stats(), Drain(b));
  };
  const auto [s1, r1] = run(42);
  const auto [s2, r2] = run(42);
  const auto [s3, r3] = run(43);
  EXPECT_EQ(r1, r2);
  EXPECT_EQ(s1.dropped, s2.dropped);
  EXPECT_NE(r1, r3);
  // ~1000 eligible frames: about 100 drops, 50 of each other fault; 0x181 frames untouched.
  EXPECT_GT(s1.dropped, 60u);
  EXPECT_LT(s1.dropped, 140u);
  EXPECT_GT(s1.duplicated, 25u);
  EXPECT_GT(s1.corrupted, 25u);
  EXPECT_GT(s1.destroyed, 25u);
  size_t untouched = 0;
  for (const CanFrame& f : r1) untouched += f.id == 0x181;
  EXPECT_EQ(untouched, 1000u);
}

TEST(CanIoSimBus, ReceiveQueueOverrun) {
  SimBus bus(1000000);
  Endpoint& a = bus.Attach("a");
  Endpoint& b = bus.Attach("b");
  b.set_rx_capacity(2);
  for (int i = 0; i < 5; ++i) a.Send(Frame(0x100));
  bus.RunUntilIdle();
  EXPECT_EQ(b.rx_pending(), 2u);
  EXPECT_EQ(bus.stats().rx_overruns, 3u);
}

// A node whose controller runs at another bit rate is off the bus (ISO 11898-1 error handling:
// transmit error counter +8 per failed transmission, bus-off at 256).
TEST(CanIoSimBus, AnEndpointAtAnotherBitRateIsOffTheBus) {
  SimBus bus(1000000);
  SimBusCanPort node(bus.Attach("node"));
  Endpoint& pc = bus.Attach("pc");
  hal::CanPort& port = node;
  ASSERT_TRUE(port.SetBitrate(1000000).ok());  // the bus's rate: on the bus
  EXPECT_TRUE(port.Send(Frame(0x701, {0x00})).ok());
  pc.Send(Frame(0x610, {1}));
  bus.RunUntilIdle();
  EXPECT_EQ(Drain(pc).size(), 1u);
  EXPECT_EQ(node.endpoint().rx_pending(), 1u);

  ASSERT_TRUE(port.SetBitrate(500000).ok());    // a controller cannot know the bus's rate
  EXPECT_EQ(node.endpoint().rx_pending(), 0u);  // re-initialised: queues emptied
  pc.Send(Frame(0x610, {2}));
  EXPECT_TRUE(port.Send(Frame(0x701, {0x00})).ok());
  std::vector<FrameRecord> records;
  bus.SetMonitor([&](const FrameRecord& r) { records.push_back(r); });
  bus.RunUntilIdle();
  EXPECT_EQ(node.endpoint().rx_pending(), 0u);  // hears nothing
  EXPECT_EQ(node.endpoint().stats().rate_errors, 1u + 32u);
  EXPECT_TRUE(Drain(pc).empty());  // nothing it sends arrives
  EXPECT_EQ(bus.stats().bitrate_errors, 32u);
  EXPECT_EQ(node.endpoint().tx_errors(), 256u);
  EXPECT_TRUE(node.endpoint().bus_off());
  EXPECT_EQ(node.endpoint().tx_pending(), 0u);
  // Each attempt: SOF, error flag, delimiter, intermission.
  for (const FrameRecord& r : records) {
    if (r.sender != node.endpoint().index()) continue;
    EXPECT_EQ(r.idle_ns - r.start_ns, (1u + 6u + 8u + 3u) * 1000u);
  }
  EXPECT_EQ(port.Send(Frame(0x701, {0x00})).error(), Error::kIoError);  // bus-off
  // Set up again at the bus's rate: back on the bus.
  ASSERT_TRUE(port.SetBitrate(1000000).ok());
  EXPECT_FALSE(node.endpoint().bus_off());
  EXPECT_TRUE(port.Send(Frame(0x701, {0x00})).ok());
  bus.RunUntilIdle();
  EXPECT_EQ(Drain(pc).size(), 1u);
}

}  // namespace
}  // namespace volcomp::sim
