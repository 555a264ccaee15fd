// Our SDO client against our SDO server over a faulty link (dropped, duplicated, delayed frames
// in both directions), in virtual time: every transfer ends either with exactly the data sent or
// with a clean failure on both sides, and the next transfer succeeds.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <functional>
#include <random>

#include "test_values.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"

namespace volcomp {
namespace {

struct Faults {
  double drop = 0, duplicate = 0, delay = 0;
  // Frames to the client that this returns true for are lost (a chosen loss); may be empty.
  std::function<bool(const CanFrame&)> lose_to_client;
};

// Node 0x10 with the test's object values, no heartbeat.
struct ServerNode {
  ServerNode() {
    node.Start(0x10, &values, 0);
    node.set_heartbeat_ms(0);
  }
  testing::TestValues values;
  canopen::Node node;
};

Faults RandomFaults(double drop, double duplicate, double delay) {
  Faults f;
  f.drop = drop;
  f.duplicate = duplicate;
  f.delay = delay;
  return f;
}

struct LinkRun {
  bool ok = false;
  canopen::SdoAbort abort_code = canopen::SdoAbort::kNone;
};

// Moves frames both ways with faults; 1 ms virtual steps. Returns the client's result.
LinkRun Transfer(canopen::Node& node,
                 canopen_client::SdoClient& client,
                 std::mt19937_64& rng,
                 const Faults& faults,
                 uint64_t* now_ms) {
  std::uniform_real_distribution<double> u(0, 1);
  std::deque<std::pair<uint64_t, CanFrame>> to_server, to_client;
  auto push = [&](std::deque<std::pair<uint64_t, CanFrame>>& q, const CanFrame& f) {
    if (u(rng) < faults.drop) return;
    if (&q == &to_client && faults.lose_to_client && faults.lose_to_client(f)) return;
    const uint64_t due = *now_ms + (u(rng) < faults.delay ? 50 : 0);
    q.emplace_back(due, f);
    if (u(rng) < faults.duplicate) q.emplace_back(due, f);
  };
  for (int step = 0; step < 20000 && !client.done(); ++step) {
    CanFrame f;
    while (client.PopTx(&f)) push(to_server, f);
    while (!to_server.empty() && to_server.front().first <= *now_ms) {
      node.OnFrame(to_server.front().second, static_cast<uint32_t>(*now_ms));
      to_server.pop_front();
    }
    node.Poll(static_cast<uint32_t>(*now_ms));
    while (node.PopTx(&f)) push(to_client, f);
    while (!to_client.empty() && to_client.front().first <= *now_ms) {
      client.OnFrame(to_client.front().second, *now_ms * 1000);
      to_client.pop_front();
    }
    client.Poll(*now_ms * 1000);
    ++*now_ms;
  }
  // Deliver the client's final frames (an abort) and let the server settle.
  CanFrame f;
  while (client.PopTx(&f)) node.OnFrame(f, static_cast<uint32_t>(*now_ms));
  for (int i = 0; i < 1500 && node.sdo().busy(); ++i) node.Poll(static_cast<uint32_t>(++*now_ms));
  while (node.PopTx(&f)) {
  }
  return {client.result().ok(), canopen_client::AbortOf(client.result())};
}

TEST(SdoFaultInjection, EveryTransferSucceedsExactlyOrFailsCleanly) {
  std::mt19937_64 rng(77);
  ServerNode server;
  testing::TestValues& values = server.values;
  canopen::Node& node = server.node;
  uint64_t now_ms = 0;
  int ok = 0, failed = 0;
  uint32_t resent = 0;
  const Faults faults = RandomFaults(0.01, 0.01, 0.005);
  const int trials = 300;
  for (int t = 0; t < trials; ++t) {
    std::vector<uint8_t> data(1 + rng() % 3000);
    for (auto& b : data) b = static_cast<uint8_t>(rng());
    canopen_client::SdoClient client(0x10);
    client.StartWrite(0x2100, 0, data);
    const int ends_before = values.ends_ok;
    const LinkRun r = Transfer(node, client, rng, faults, &now_ms);
    resent += client.resent_segments();
    ASSERT_FALSE(node.sdo().busy()) << "trial " << t;
    if (r.ok) {
      ++ok;
      ASSERT_EQ(values.domain, data) << "trial " << t;
      ASSERT_EQ(values.ends_ok, ends_before + 1);
    } else {
      ++failed;
      ASSERT_NE(r.abort_code, canopen::SdoAbort::kNone);
      // The server did not complete the write, or completed it with exactly the data (its final
      // acknowledgement was lost): never anything else.
      if (values.ends_ok != ends_before) {
        ASSERT_EQ(values.domain, data);
      }
      // A retry over a clean link succeeds.
      canopen_client::SdoClient retry(0x10);
      retry.StartWrite(0x2100, 0, data);
      const LinkRun again = Transfer(node, retry, rng, Faults{}, &now_ms);
      ASSERT_TRUE(again.ok) << "retry after trial " << t;
      ASSERT_EQ(values.domain, data);
    }
  }
  std::printf(
      "[ metric ] SDO block download over a faulty link: %d trials, %d ok, %d failed "
      "cleanly (then retried ok), %u segments resent\n",
      trials, ok, failed, resent);
  EXPECT_GT(ok, trials / 2);
  EXPECT_GT(resent, 0u);
}

// A block upload whose sub-block loses its last segment (the client's receive buffer overflowed):
// the client acknowledges what it has after block_gap_ms of silence and the node sends the rest
// again, well within the node's own 1000 ms timeout. Without that the node times out.
TEST(SdoFaultInjection, BlockUploadRecoversFromALostLastSegment) {
  ServerNode server;
  testing::TestValues& values = server.values;
  canopen::Node& node = server.node;
  values.domain_readback.resize(624);  // 90 segments: one sub-block, as 0x2124 on the board
  for (size_t i = 0; i < values.domain_readback.size(); ++i) {
    values.domain_readback[i] = static_cast<uint8_t>(i * 7 + 3);
  }
  std::mt19937_64 rng(1);
  uint64_t now_ms = 0;
  for (const uint32_t gap_ms : {200u, 0u}) {
    int lost = 0;
    Faults faults;
    faults.lose_to_client = [&](const CanFrame& f) {
      // The first block segment carrying the "last" flag (0x80) with sequence number 90.
      if (lost == 0 && f.id == 0x590 && f.data[0] == (0x80 | 90)) return ++lost == 1;
      return false;
    };
    canopen_client::SdoClient::Options options;
    options.block_gap_ms = gap_ms;
    canopen_client::SdoClient c(0x10, options);
    c.StartRead(0x2100, 0, true);
    const uint64_t start_ms = now_ms;
    const LinkRun r = Transfer(node, c, rng, faults, &now_ms);
    EXPECT_EQ(lost, 1);
    if (gap_ms != 0) {
      ASSERT_TRUE(r.ok) << c.result().error().message;
      EXPECT_EQ(*c.result(), values.domain_readback);
      EXPECT_EQ(c.gap_acks(), 1u);
      EXPECT_LT(now_ms - start_ms, 400u);  // one gap, not a timeout
    } else {
      EXPECT_FALSE(r.ok);
      EXPECT_EQ(r.abort_code, canopen::SdoAbort::kTimeout);  // the node's, after 1000 ms
      EXPECT_EQ(c.gap_acks(), 0u);
    }
  }
}

// Block uploads over a lossy, duplicating, delaying link: each ends with exactly the object's
// bytes or with a clean failure (an abort), most of them succeed, and gap acknowledgements occur.
TEST(SdoFaultInjection, BlockUploadsOverAFaultyLinkAreExactOrFailCleanly) {
  std::mt19937_64 rng(11);
  ServerNode server;
  testing::TestValues& values = server.values;
  canopen::Node& node = server.node;
  uint64_t now_ms = 0;
  int ok = 0;
  uint32_t gap_acks = 0;
  const int trials = 200;
  for (int t = 0; t < trials; ++t) {
    values.domain_readback.resize(1 + rng() % 2000);
    for (auto& b : values.domain_readback) b = static_cast<uint8_t>(rng());
    canopen_client::SdoClient c(0x10);
    c.StartRead(0x2100, 0, true);
    const LinkRun r = Transfer(node, c, rng, RandomFaults(0.01, 0.01, 0.005), &now_ms);
    gap_acks += c.gap_acks();
    ASSERT_FALSE(node.sdo().busy()) << "trial " << t;
    if (r.ok) {
      ++ok;
      ASSERT_EQ(*c.result(), values.domain_readback) << "trial " << t;
    } else {
      ASSERT_NE(r.abort_code, canopen::SdoAbort::kNone) << c.result().error().message;
    }
  }
  std::printf(
      "[ metric ] SDO block upload over a faulty link: %d trials, %d ok, %u gap "
      "acknowledgements\n",
      trials, ok, gap_acks);
  EXPECT_GT(ok, trials * 8 / 10);
  EXPECT_GT(gap_acks, 0u);
}

TEST(SdoFaultInjection, UploadsAndSmallWritesOverACleanLink) {
  std::mt19937_64 rng(5);
  ServerNode server;
  testing::TestValues& values = server.values;
  canopen::Node& node = server.node;
  uint64_t now_ms = 0;
  for (size_t n : {0u, 1u, 6u, 7u, 8u, 127u * 7u, 127u * 7u + 1u, 5000u}) {
    values.domain_readback.resize(n);
    for (auto& b : values.domain_readback) b = static_cast<uint8_t>(rng());
    for (bool block : {false, true}) {
      canopen_client::SdoClient c(0x10);
      c.StartRead(0x2100, 0, block);
      ASSERT_TRUE(Transfer(node, c, rng, Faults{}, &now_ms).ok) << n << (block ? " block" : "");
      EXPECT_EQ(*c.result(), values.domain_readback) << n;
    }
  }
  // Segmented (non-block) download and expedited writes.
  canopen_client::SdoClient::Options seg;
  seg.use_block = false;
  std::vector<uint8_t> data(100, 0x5A);
  canopen_client::SdoClient c(0x10, seg);
  c.StartWrite(0x2100, 0, data);
  ASSERT_TRUE(Transfer(node, c, rng, Faults{}, &now_ms).ok);
  EXPECT_EQ(values.domain, data);
  canopen_client::SdoClient w(0x10);
  w.StartWrite(0x1017, 0, {0x34, 0x12});
  ASSERT_TRUE(Transfer(node, w, rng, Faults{}, &now_ms).ok);
  EXPECT_EQ(node.heartbeat_ms(), 0x1234);
  canopen_client::SdoClient bad(0x10);
  bad.StartWrite(0x1000, 0, {1, 2, 3, 4});
  const LinkRun r = Transfer(node, bad, rng, Faults{}, &now_ms);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(canopen::Code(r.abort_code), 0x06010002u);
  ASSERT_FALSE(bad.result().ok());
  EXPECT_TRUE(bad.result().error().by_server);
  EXPECT_NE(bad.result().error().message.find("attempt to write a read-only object"),
            std::string::npos)
      << bad.result().error().message;
}

}  // namespace
}  // namespace volcomp
