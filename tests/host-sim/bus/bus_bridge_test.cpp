// The bridges between SimBus endpoints and external links: an SLCAN-over-TCP client served over
// the bus in real time, and what a disconnected client's session leaves on the bus.
#include "volcomp/sim/bus_bridge.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <string>
#include <thread>

#include "can_frames.hpp"
#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/can_io/transport.hpp"
#include "volcomp/sim/realtime.hpp"

namespace volcomp::sim {
namespace {

CanFrame Frame(uint32_t id, std::vector<uint8_t> data = {}, bool ext = false, bool rtr = false) {
  return testing::Frame(id, ext, rtr, std::move(data));
}

TEST(CanIoSimBus, SlcanBridgeServesAClientOverTheBus) {
  // The simulator shape: an SLCAN TCP server bridged to endpoint "pc", a responder node on the
  // bus, the bus paced to the wall clock on a thread; the client talks through OpenTransport.
  SimBus bus(1000000);
  Endpoint& pc = bus.Attach("pc");
  Endpoint& node = bus.Attach("node");
  node.SetReceiveCallback([&](const CanFrame& f, uint64_t) {
    CanFrame r = f;
    r.id = 0x580 + (f.id & 0x7F);
    node.Send(r);
  });
  auto created = can_io::SlcanServer::CreateTcp("127.0.0.1", 0);
  ASSERT_TRUE(created.ok()) << created.error().message;
  auto& server = *created;
  const std::string spec = server->client_spec();
  std::atomic<bool> stop{false};
  std::string failure;  // the serving thread's, read after join
  std::thread sim([&] {
    const RealtimeClock clock;
    while (!stop) {
      const Outcome served =
          RunRealtime(bus, clock, clock.Now() + 2000000, [&](std::chrono::microseconds t) {
            return ServeSlcan(*server, pc, std::min(t, std::chrono::microseconds(1000)));
          });
      if (!served.ok()) {
        failure = served.error().message;
        return;
      }
    }
  });
  {
    auto opened = can_io::OpenTransport(spec + "@1M");
    ASSERT_TRUE(opened.ok()) << opened.error().message;
    auto& client = *opened;
    const auto t0 = std::chrono::steady_clock::now();
    constexpr int kFrames = 200;
    for (int i = 0; i < kFrames; ++i) {
      ASSERT_TRUE(client->Send(Frame(0x601, {uint8_t(i), 0, 0, 0, 0, 0, 0, 0})).ok());
      const auto received = client->Receive(std::chrono::milliseconds(1000));
      ASSERT_TRUE(received.ok()) << received.error().message;
      const std::optional<CanFrame>& got = *received;
      ASSERT_TRUE(got) << i;
      EXPECT_EQ(got->id, 0x581u);
      EXPECT_EQ(got->data[0], uint8_t(i));
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("[ sim bus + slcan-tcp ] request/response pairs: %.0f /s\n", kFrames / s);
  }
  stop = true;
  sim.join();
  EXPECT_EQ(failure, "");
  EXPECT_EQ(bus.stats().frames, 400u);
}

// A raw SLCAN-over-TCP client for frame-level checks: what it sends and every line it received.
class RawSlcanClient {
 public:
  explicit RawSlcanClient(uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  }
  ~RawSlcanClient() { Close(); }
  void Write(const std::string& text) {
    ASSERT_EQ(::send(fd_, text.data(), text.size(), MSG_NOSIGNAL), ssize_t(text.size()));
  }
  void Close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  // Frame lines ("t...") received so far.
  std::vector<std::string> Frames() {
    char buf[4096];
    for (;;) {
      const ssize_t n = ::recv(fd_, buf, sizeof buf, MSG_DONTWAIT);
      if (n <= 0) break;
      text_.append(buf, size_t(n));
    }
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t i = 0; i < text_.size(); ++i) {
      if (text_[i] != '\r') continue;
      if (text_[start] == 't') out.push_back(text_.substr(start, i - start));
      start = i + 1;
    }
    return out;
  }

 private:
  int fd_ = -1;
  std::string text_;
};

// A client that disconnects leaves the node's answers to it queued on the bus (here 40 frames
// 0x590 from "node"); they are dropped, not handed to the next client. The next client's request
// reaches the node once that traffic is over, and its answer (0x591) reaches the client.
TEST(CanIoSimBus, SlcanBridgeDropsWhatWasQueuedForADisconnectedClient) {
  SimBus bus(1000000);
  Endpoint& pc = bus.Attach("pc");
  Endpoint& node = bus.Attach("node");
  auto created = can_io::SlcanServer::CreateTcp("127.0.0.1", 0);
  ASSERT_TRUE(created.ok()) << created.error().message;
  auto& server = *created;
  SlcanBridge bridge(bus, *server, pc);
  const auto serve = [&] { EXPECT_TRUE(bridge.Serve(std::chrono::microseconds(200)).ok()); };
  const auto advance = [&](uint64_t ns) {  // bus time in 100 us steps, serving in between
    for (uint64_t t = 0; t < ns; t += 100000) {
      bus.RunUntil(bus.now() + 100000);
      serve();
    }
  };
  RawSlcanClient first(server->port());
  first.Write("O\r");
  for (int i = 0; i < 50 && !server->channel_open(); ++i) serve();
  ASSERT_TRUE(server->channel_open());
  first.Write("t6018A300000000000000\r");  // the request the node answers with a burst
  advance(1000000);
  CanFrame request;
  ASSERT_TRUE(node.Receive(&request));
  for (int i = 0; i < 40; ++i) node.Send(Frame(0x590, {uint8_t(i), 0, 0, 0, 0, 0, 0, 0}));
  advance(500000);  // a few of them reach the first client
  EXPECT_FALSE(first.Frames().empty());
  first.Close();
  RawSlcanClient second(server->port());
  for (int i = 0; i < 50 && server->stats().clients < 2; ++i) serve();
  ASSERT_EQ(server->stats().clients, 2u);
  second.Write("O\rt60184004210000000000\r");
  for (int i = 0; i < 10; ++i) serve();
  // The node answers whatever reaches it with 0x591.
  std::vector<CanFrame> requests;
  for (int step = 0; step < 200; ++step) {
    advance(100000);
    CanFrame f;
    while (node.Receive(&f)) {
      requests.push_back(f);
      node.Send(Frame(0x591, {f.data[0], 0, 0, 0, 0, 0, 0, 0}));
    }
  }
  ASSERT_EQ(requests.size(), 1u) << "dropped " << bridge.dropped() << ", from client "
                                 << server->stats().frames_from_client << ", pc queued "
                                 << pc.tx_pending() << ", bus idle " << bus.idle();
  EXPECT_EQ(requests[0].id, 0x601u);
  EXPECT_EQ(requests[0].data[0], 0x40);
  const std::vector<std::string> got = second.Frames();
  EXPECT_EQ(got, std::vector<std::string>{"t59184000000000000000"});
  EXPECT_GT(bridge.dropped(), 0u);
}

}  // namespace
}  // namespace volcomp::sim
