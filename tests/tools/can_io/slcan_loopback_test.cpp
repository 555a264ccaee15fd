// SlcanServer (device side) against raw clients and against the SLCAN client transports, over
// TCP (port 0, read back) and over a pty made with openpty(). Also measures loopback rates.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <thread>

#include "can_frames.hpp"
#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/can_io/slcan_transport.hpp"
#include "volcomp/can_io/transport.hpp"

namespace volcomp::can_io {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

using testing::Frame;

// The object a factory made, or null after recording its failure (check with ASSERT_TRUE).
template <typename T>
std::unique_ptr<T> Created(Expected<std::unique_ptr<T>> made) {
  if (!made.ok()) {
    ADD_FAILURE() << made.error().message;
    return nullptr;
  }
  return std::move(made).value();
}

// The next frame within `timeout`, or nullopt (a failure of the link is recorded).
std::optional<CanFrame> Next(CanTransport& t, microseconds timeout) {
  const Expected<std::optional<CanFrame>> got = t.Receive(timeout);
  if (!got.ok()) {
    ADD_FAILURE() << got.error().message;
    return std::nullopt;
  }
  return *got;
}

void Sent(CanTransport& t, const CanFrame& f) {
  const Outcome sent = t.Send(f);
  EXPECT_TRUE(sent.ok()) << sent.error().message;
}

// The i-th frame of a test sequence: standard, extended and remote frames of every length.
CanFrame TestFrame(uint32_t i) {
  CanFrame f;
  f.extended = i % 3 == 1;
  f.rtr = i % 7 == 3;
  f.id = f.extended ? (0x1000000u + i * 7919u) & 0x1FFFFFFFu : (i * 37u) & 0x7FFu;
  f.dlc = static_cast<uint8_t>(i % 9);
  for (uint8_t b = 0; b < 8; ++b) f.data[b] = static_cast<uint8_t>(i * 13 + b);
  return f;
}

// What the echo server answers: the same frame with the id's lowest bit flipped.
CanFrame Echo(CanFrame f) {
  f.id ^= 1u;
  return f;
}

// Runs a server's Poll loop on a thread, answering each received frame with Echo().
class ServerThread {
 public:
  explicit ServerThread(std::unique_ptr<SlcanServer> server) : server_(std::move(server)) {
    spec_ = server_->client_spec();
    thread_ = std::thread([this] {
      while (!stop_) {
        EXPECT_TRUE(server_->Poll(milliseconds(1)).ok());
        for (const CanFrame& f : server_->TakeReceived()) server_->Send(Echo(f));
      }
    });
  }
  ~ServerThread() { Stop(); }
  void Stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  const std::string& spec() const { return spec_; }
  // Only after Stop().
  SlcanServer& server() { return *server_; }
  void Destroy() {
    Stop();
    server_.reset();
  }

 private:
  std::unique_ptr<SlcanServer> server_;
  std::string spec_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// A raw byte-level client on one thread with the server (the test drives both).
class RawClient {
 public:
  RawClient(SlcanServer* server, int fd) : server_(server), fd_(fd) {}
  ~RawClient() {
    if (fd_ >= 0) ::close(fd_);
  }
  void CloseNow() {
    ::close(fd_);
    fd_ = -1;
  }
  // Sends `text` and returns the reply once `expect.size()` bytes arrived (or after 1 s).
  std::string Say(const std::string& text, size_t expect) {
    if (!text.empty()) {
      EXPECT_EQ(::write(fd_, text.data(), text.size()), ssize_t(text.size()));
    }
    return Collect(expect, milliseconds(1000));
  }
  std::string Collect(size_t expect, milliseconds limit) {
    std::string got;
    const auto deadline = Clock::now() + limit;
    while (got.size() < expect && Clock::now() < deadline) {
      EXPECT_TRUE(server_->Poll(microseconds(500)).ok());
      char buf[256];
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n > 0) got.append(buf, static_cast<size_t>(n));
    }
    return got;
  }
  int fd() const { return fd_; }

 private:
  SlcanServer* server_;
  int fd_;
};

int ConnectTcp(uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);  // EINPROGRESS is fine on loopback
  return fd;
}

int OpenPtyRaw(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  termios t{};
  ::tcgetattr(fd, &t);
  ::cfmakeraw(&t);
  ::tcsetattr(fd, TCSANOW, &t);
  return fd;
}

// The adapter behaviour every SLCAN client relies on (can-protocols.md §3.1).
void CheckAdapterDialogue(SlcanServer& server, RawClient& c) {
  EXPECT_EQ(c.Say("t1230\r", 1), "\a");  // channel closed: frames refused
  EXPECT_EQ(c.Say("\r\rC\r", 1), "\r");  // leading CRs skipped, C acknowledged
  EXPECT_EQ(c.Say("S8\r", 1), "\r");
  EXPECT_EQ(server.bitrate(), 1000000u);
  EXPECT_EQ(c.Say("S7\r", 1), "\r");
  EXPECT_EQ(server.bitrate(), 800000u);  // the standard table (python-can would mean 750k)
  EXPECT_EQ(c.Say("S9\r", 1), "\r");
  EXPECT_EQ(server.bitrate(), 83333u);
  EXPECT_EQ(c.Say("S8\rO\rO\r", 3), "\r\r\r");  // python-can sends O twice
  EXPECT_TRUE(server.channel_open());
  EXPECT_EQ(c.Say("t1232AABB\r", 2), "z\r");
  EXPECT_EQ(c.Say("T1ABCDEF01FF\r", 2), "Z\r");
  EXPECT_EQ(c.Say("r7FF0\r", 2), "z\r");
  const auto got = server.TakeReceived();
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], Frame(0x123, false, false, {0xAA, 0xBB}));
  EXPECT_EQ(got[1], Frame(0x1ABCDEF0, true, false, {0xFF}));
  EXPECT_EQ(got[2], Frame(0x7FF, false, true, {}));
  EXPECT_EQ(c.Say("F\r", 4), "F00\r");
  EXPECT_EQ(c.Say("V\r", 6), "V0100\r");
  EXPECT_EQ(c.Say("v\r", 6), "v0100\r");
  EXPECT_EQ(c.Say("N\r", 6), "NVC01\r");
  EXPECT_EQ(c.Say("X1\rs031C\rM00000000\rmFFFFFFFF\rU2\r", 5), "\r\r\r\r\r");
  EXPECT_EQ(c.Say("X0\rP\rA\rQ1\rt12\rhello\r", 6), "\a\a\a\a\a\a");
  // Frames from the bus, with and without timestamps.
  server.Send(Frame(0x581, false, false, {0x60, 0x00, 0x21, 0x01, 0, 0, 0, 0}));
  EXPECT_EQ(c.Say("", 22), "t58186000210100000000\r");
  EXPECT_EQ(c.Say("Z1\r", 1), "\r");
  server.Send(Frame(0x100, false, false, {}));
  const std::string ts = c.Say("", 10);
  ASSERT_EQ(ts.size(), 10u) << ts;
  EXPECT_EQ(ts.substr(0, 5), "t1000");
  EXPECT_EQ(c.Say("Z0\r", 1), "\r");
  // Listen-only refuses frames, C closes, frames to a closed channel are dropped.
  EXPECT_EQ(c.Say("L\rt1230\r", 2), "\r\a");
  EXPECT_TRUE(server.listen_only());
  EXPECT_EQ(c.Say("C\r", 1), "\r");
  const uint64_t dropped = server.stats().frames_dropped;
  server.Send(Frame(0x100, false, false, {}));
  EXPECT_EQ(server.stats().frames_dropped, dropped + 1);
  EXPECT_EQ(c.Collect(1, milliseconds(20)), "");
  EXPECT_EQ(server.stats().frames_from_client, 3u);
}

TEST(CanIoSlcanServer, TcpAnswersLikeAnAdapter) {
  auto server = Created(SlcanServer::CreateTcp("127.0.0.1", 0));
  ASSERT_TRUE(server);
  ASSERT_NE(server->port(), 0);
  EXPECT_EQ(server->client_spec(), "slcan-tcp:127.0.0.1:" + std::to_string(server->port()));
  RawClient c(server.get(), ConnectTcp(server->port()));
  CheckAdapterDialogue(*server, c);
  EXPECT_EQ(server->stats().clients, 1u);
}

TEST(CanIoSlcanServer, PtyAnswersLikeAnAdapter) {
  auto server = Created(SlcanServer::CreatePty());
  ASSERT_TRUE(server);
  EXPECT_EQ(server->endpoint().rfind("/dev/pts/", 0), 0u) << server->endpoint();
  RawClient c(server.get(), OpenPtyRaw(server->endpoint()));
  CheckAdapterDialogue(*server, c);
}

TEST(CanIoSlcanServer, TcpServesTheNextClientAfterADisconnect) {
  auto server = Created(SlcanServer::CreateTcp("127.0.0.1", 0));
  ASSERT_TRUE(server);
  RawClient a(server.get(), ConnectTcp(server->port()));
  EXPECT_EQ(a.Say("O\r", 1), "\r");
  EXPECT_TRUE(server->channel_open());
  // One client at a time: the second waits in the backlog, unanswered.
  RawClient b(server.get(), ConnectTcp(server->port()));
  ASSERT_EQ(::write(b.fd(), "V\r", 2), 2);
  EXPECT_EQ(b.Collect(1, milliseconds(30)), "");
  a.CloseNow();
  // The server notices the disconnect, resets the session and accepts b, whose V is pending.
  EXPECT_EQ(b.Collect(6, milliseconds(1000)), "V0100\r");
  EXPECT_FALSE(server->channel_open());
  EXPECT_EQ(server->stats().clients, 2u);
  EXPECT_EQ(b.Say("t1230\r", 1), "\a");  // the new session starts closed
}

TEST(CanIoSlcanServer, PtySymlink) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("volcomp-slcan-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto link = dir / "ttySIM";
  {
    SlcanServerOptions o;
    o.symlink = link.string();
    auto server = Created(SlcanServer::CreatePty(o));
    ASSERT_TRUE(server);
    ASSERT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_EQ(std::filesystem::read_symlink(link).string(), server->endpoint());
    // A stale symlink is replaced by the next server.
    auto second = Created(SlcanServer::CreatePty(o));
    ASSERT_TRUE(second);
    EXPECT_EQ(std::filesystem::read_symlink(link).string(), second->endpoint());
    second.reset();
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
  }
  // A regular file at the link path is never replaced.
  {
    std::FILE* f = std::fopen(link.c_str(), "w");
    std::fclose(f);
  }
  SlcanServerOptions o;
  o.symlink = link.string();
  const auto refused = SlcanServer::CreatePty(o);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kIoError);
  EXPECT_NE(refused.error().message.find("exists and is not a symlink"), std::string::npos)
      << refused.error().message;
  std::filesystem::remove_all(dir);
}

// Ping-pong through OpenTransport(): every frame kind, then the adapter queries.
void RoundTrip(ServerThread& st, const std::string& spec, const char* label) {
  auto client = Created(OpenTransport(spec + "@1M"));
  ASSERT_TRUE(client);
  EXPECT_NE(client->description().find("@1000000"), std::string::npos);
  constexpr uint32_t kFrames = 300;
  const auto t0 = Clock::now();
  for (uint32_t i = 0; i < kFrames; ++i) {
    const CanFrame f = TestFrame(i);
    Sent(*client, f);
    const auto got = Next(*client, milliseconds(1000));
    ASSERT_TRUE(got) << "frame " << i;
    ASSERT_EQ(*got, Echo(f)) << "frame " << i;
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("[ %s ] ping-pong round trips: %.0f /s\n", label, kFrames / s);
  EXPECT_FALSE(Next(*client, microseconds(0)));
  EXPECT_TRUE(client->TakeEvents().empty());
  auto* slcan = dynamic_cast<SlcanTransport*>(client.get());
  ASSERT_NE(slcan, nullptr);
  EXPECT_EQ(*slcan->Command("V", milliseconds(500)), "V0100");
  EXPECT_EQ(*slcan->Command("N", milliseconds(500)), "NVC01");
  EXPECT_EQ(*slcan->Command("F", milliseconds(500)), "F00");
  const auto refused = slcan->Command("P", milliseconds(500));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kCommunication);
  EXPECT_NE(refused.error().message.find("adapter answered BEL to 'P'"), std::string::npos)
      << refused.error().message;
  client.reset();  // sends C and disconnects
  st.Stop();
  // Let the server see the C / the disconnect (it is ours to poll now).
  const auto deadline = Clock::now() + milliseconds(1000);
  while (st.server().channel_open() && Clock::now() < deadline) {
    EXPECT_TRUE(st.server().Poll(milliseconds(1)).ok());
  }
  EXPECT_EQ(st.server().bitrate(), 1000000u);
  EXPECT_FALSE(st.server().channel_open());
  EXPECT_EQ(st.server().stats().frames_from_client, kFrames);
  EXPECT_EQ(st.server().stats().frames_to_client, kFrames);
}

TEST(CanIoSlcanLoopback, TcpRoundTrip) {
  auto server = Created(SlcanServer::CreateTcp("127.0.0.1", 0));
  ASSERT_TRUE(server);
  ServerThread st(std::move(server));
  RoundTrip(st, st.spec(), "slcan-tcp");
}

TEST(CanIoSlcanLoopback, PtyRoundTrip) {
  auto server = Created(SlcanServer::CreatePty());
  ASSERT_TRUE(server);
  ServerThread st(std::move(server));
  RoundTrip(st, st.spec(), "slcan pty");
}

// Streaming with up to 64 frames in flight: the rate an SDO block transfer can use.
void Stream(const std::string& spec, const char* label) {
  auto client = Created(OpenTransport(spec));
  ASSERT_TRUE(client);
  constexpr uint32_t kFrames = 4000;
  constexpr uint32_t kWindow = 64;
  uint32_t sent = 0;
  uint32_t received = 0;
  const auto t0 = Clock::now();
  while (received < kFrames) {
    while (sent < kFrames && sent - received < kWindow) Sent(*client, TestFrame(sent++));
    const auto got = Next(*client, milliseconds(1000));
    ASSERT_TRUE(got) << "after " << received;
    ASSERT_EQ(*got, Echo(TestFrame(received))) << received;  // order is kept
    ++received;
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("[ %s ] streamed echo: %.0f frames/s each way\n", label, kFrames / s);
  // Far above the ~7.4k-9k frames/s a 1 Mbit/s bus carries.
  EXPECT_GT(kFrames / s, 5000.0);
}

TEST(CanIoSlcanLoopback, TcpStreaming) {
  auto server = Created(SlcanServer::CreateTcp("127.0.0.1", 0));
  ASSERT_TRUE(server);
  ServerThread st(std::move(server));
  Stream(st.spec(), "slcan-tcp");
}

TEST(CanIoSlcanLoopback, PtyStreaming) {
  auto server = Created(SlcanServer::CreatePty());
  ASSERT_TRUE(server);
  ServerThread st(std::move(server));
  Stream(st.spec(), "slcan pty");
}

TEST(CanIoSlcanLoopback, ClientSeesTheServerGo) {
  for (bool pty : {false, true}) {
    auto server = Created(pty ? SlcanServer::CreatePty() : SlcanServer::CreateTcp("127.0.0.1", 0));
    ASSERT_TRUE(server);
    ServerThread st(std::move(server));
    auto client = Created(OpenTransport(st.spec()));
    ASSERT_TRUE(client);
    Sent(*client, TestFrame(1));
    ASSERT_TRUE(Next(*client, milliseconds(1000)));
    st.Destroy();
    const auto gone = client->Receive(milliseconds(1000));
    ASSERT_FALSE(gone.ok()) << "no error after the server closed (" << (pty ? "pty" : "tcp") << ")";
    EXPECT_EQ(gone.error().code, Error::kCommunication);
    const std::string& what = gone.error().message;
    EXPECT_TRUE(what.find("closed") != std::string::npos ||
                what.find("device gone") != std::string::npos)
        << what;
  }
}

TEST(CanIoSlcanLoopback, SilentAdapterIsTolerated) {
  // A TCP peer that never answers: opening waits once for the C answer, then carries on.
  auto server = Created(SlcanServer::CreateTcp("127.0.0.1", 0));  // never polled: nobody answers
  ASSERT_TRUE(server);
  SlcanOptions o;
  o.bitrate = 500000;
  o.open_timeout = milliseconds(50);
  const auto t0 = Clock::now();
  auto client = Created(OpenSlcanTcp("127.0.0.1", server->port(), o));
  ASSERT_TRUE(client);
  EXPECT_LT(Clock::now() - t0, milliseconds(500));
  EXPECT_FALSE(Next(*client, microseconds(0)));
}

// A scripted fake adapter on a TCP listener: answers each line with answer(line).
class FakeAdapter {
 public:
  explicit FakeAdapter(std::function<std::string(const std::string&)> answer)
      : answer_(std::move(answer)) {
    listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::bind(listener_, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
    ::listen(listener_, 1);
    socklen_t len = sizeof a;
    ::getsockname(listener_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] {
      const int fd = ::accept(listener_, nullptr, nullptr);
      std::string line;
      char c;
      while (::read(fd, &c, 1) == 1) {
        if (c != '\r') {
          line += c;
          continue;
        }
        const std::string reply = answer_(line);
        if (!reply.empty()) (void)!::write(fd, reply.data(), reply.size());
        line.clear();
      }
      ::close(fd);
    });
  }
  ~FakeAdapter() {
    thread_.join();
    ::close(listener_);
  }
  uint16_t port() const { return port_; }

 private:
  std::function<std::string(const std::string&)> answer_;
  int listener_ = -1;
  uint16_t port_ = 0;
  std::thread thread_;
};

TEST(CanIoSlcanLoopback, RefusedBitrateOrOpenIsAnError) {
  for (const char* refused : {"S6", "O"}) {
    FakeAdapter fake([refused](const std::string& line) {
      return line == refused ? std::string("\a") : std::string("\r");
    });
    SlcanOptions o;
    o.bitrate = 500000;
    const auto opened = OpenSlcanTcp("127.0.0.1", fake.port(), o);
    ASSERT_FALSE(opened.ok()) << "no error when the adapter refuses " << refused;
    EXPECT_EQ(opened.error().code, Error::kCommunication);
    EXPECT_NE(opened.error().message.find(std::string("adapter refused '") + refused + "'"),
              std::string::npos)
        << opened.error().message;
  }
}

TEST(CanIoSlcanLoopback, SlcanpytStyleAcksAndBelEvents) {
  // Frames acknowledged with "\r" (can-utils slcanpty style) are tolerated; a BEL after a frame
  // becomes an adapter event.
  FakeAdapter fake([](const std::string& line) {
    if (line == "t1230") return std::string("\a");
    if (line == "t1240") return std::string("\rt5551AA\r");  // ack, then a frame from the bus
    return std::string("\r");
  });
  auto client = Created(OpenSlcanTcp("127.0.0.1", fake.port(), SlcanOptions()));
  ASSERT_TRUE(client);
  Sent(*client, Frame(0x124, false, false, {}));
  const auto got = Next(*client, milliseconds(1000));
  ASSERT_TRUE(got);
  EXPECT_EQ(*got, Frame(0x555, false, false, {0xAA}));
  Sent(*client, Frame(0x123, false, false, {}));
  std::vector<BusEvent> events;
  const auto deadline = Clock::now() + milliseconds(1000);
  while (events.empty() && Clock::now() < deadline) {
    Next(*client, milliseconds(5));
    events = client->TakeEvents();
  }
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, BusEvent::Kind::kAdapterError);
}

}  // namespace
}  // namespace volcomp::can_io
