// NodeObjects repeats a read that broke on the protocol (a timeout, a stale abort from an earlier
// transfer) and never one the node refused; frames are written here by hand from CiA 301
// (expedited upload response 0x43 + index + sub + 4 data bytes; abort 0x80 + index + sub + code).
#include "volcomp/canopen_client/node_objects.hpp"

#include <gtest/gtest.h>

#include <deque>

#include "volcomp/canopen/object_dictionary.hpp"

namespace volcomp::canopen_client {
namespace {

constexpr uint8_t kNode = 0x10;

// A node whose answers to successive SDO requests are scripted: for each request one of
// "abort with code" (code != 0), "answer with value" (code == 0) or "stay silent" (silent).
struct ScriptedNode {
  struct Answer {
    uint32_t abort_code = 0;
    uint32_t value = 0;
    bool silent = false;
  };
  std::deque<Answer> script;
  std::deque<CanFrame> pending;
  int requests = 0;
  int client_aborts = 0;
  uint64_t now_us = 1000;

  FrameLink link() {
    FrameLink l;
    l.send = [this](const CanFrame& f) {
      EXPECT_EQ(f.id, 0x600u + kNode);
      if (f.data[0] == 0x80) {  // the client gives up on a transfer
        ++client_aborts;
        return Outcome::Ok();
      }
      ++requests;
      if (script.empty()) return Outcome::Ok();
      const Answer a = script.front();
      script.pop_front();
      if (a.silent) return Outcome::Ok();
      CanFrame r;
      r.id = 0x580 + kNode;
      r.dlc = 8;
      r.data[0] = a.abort_code != 0 ? 0x80 : 0x43;
      for (int i = 1; i <= 3; ++i) r.data[i] = f.data[i];  // index and sub-index
      const uint32_t payload = a.abort_code != 0 ? a.abort_code : a.value;
      for (int i = 0; i < 4; ++i) r.data[4 + i] = static_cast<uint8_t>(payload >> (8 * i));
      pending.push_back(r);
      return Outcome::Ok();
    };
    l.receive = [this](uint64_t timeout_us) -> Expected<std::optional<CanFrame>> {
      if (pending.empty()) {
        now_us += timeout_us;
        return std::optional<CanFrame>();
      }
      const CanFrame f = pending.front();
      pending.pop_front();
      return std::optional<CanFrame>(f);
    };
    l.now_us = [this] { return now_us; };
    return l;
  }
};

TEST(NodeObjects, ReadIsRepeatedOnceAfterAStaleTimeoutAbortFromTheNode) {
  ScriptedNode n;
  n.script = {{0x05040000, 0, false}, {0, 0x12345678, false}};
  const FrameLink link = n.link();
  NodeObjects objects(link, kNode);
  const SdoExpected<uint32_t> r = objects.Read(canopen::ObjectId::kActiveTableCrc);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(*r, 0x12345678u);
  EXPECT_EQ(n.requests, 2);
  EXPECT_EQ(objects.read_retries(), 1u);
}

TEST(NodeObjects, ReadIsRepeatedAfterItsOwnTimeoutThenFailsWithTheTimeout) {
  ScriptedNode n;
  n.script = {{0, 0, true}, {0, 0, true}, {0, 7, false}};
  SdoClient::Options o;
  o.timeout_ms = 10;
  const FrameLink link = n.link();
  NodeObjects objects(link, kNode, o);
  const SdoExpected<uint32_t> r = objects.Read(canopen::ObjectId::kActiveTableId);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kCommunication);
  EXPECT_EQ(canopen::Code(r.error().abort), 0x05040000u);
  EXPECT_EQ(n.requests, 2);  // the default: two attempts in all, the third answer never asked for
  EXPECT_EQ(n.client_aborts, 2);
}

TEST(NodeObjects, ARefusalIsNotRepeated) {
  ScriptedNode n;
  n.script = {{0x08000024, 0, false}, {0, 1, false}};
  const FrameLink link = n.link();
  NodeObjects objects(link, kNode);
  const SdoExpected<uint32_t> r = objects.Read(canopen::ObjectId::kActiveTableId);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(canopen::Code(r.error().abort), 0x08000024u);
  EXPECT_TRUE(r.error().by_server);
  EXPECT_EQ(n.requests, 1);
  EXPECT_EQ(objects.read_retries(), 0u);
}

TEST(NodeObjects, OneAttemptWhenTheOptionsSaySo) {
  ScriptedNode n;
  n.script = {{0x05040000, 0, false}, {0, 1, false}};
  SdoClient::Options o;
  o.read_attempts = 1;
  const FrameLink link = n.link();
  NodeObjects objects(link, kNode, o);
  EXPECT_FALSE(objects.Read(canopen::ObjectId::kActiveTableId).ok());
  EXPECT_EQ(n.requests, 1);
}

TEST(NodeObjects, WritesAreNotRepeated) {
  ScriptedNode n;
  n.script = {{0x05040000, 0, false}, {0, 0, false}};
  const FrameLink link = n.link();
  NodeObjects objects(link, kNode);
  EXPECT_FALSE(objects.Write(canopen::ObjectId::kTableControl, 1).ok());
  EXPECT_EQ(n.requests, 1);
}

}  // namespace
}  // namespace volcomp::canopen_client
