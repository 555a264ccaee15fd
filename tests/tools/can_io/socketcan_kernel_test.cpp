// SocketCAN against a real kernel: the receive filter, the kernel's count of dropped frames and the
// enlarged receive buffer of SocketCanSocket. Needs a vcan interface (default vcan0, or
// VOLCOMP_VCAN), so it is not a host ctest: tests/uml/run_uml_socketcan.sh runs it inside
// user-mode-linux, as root.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "volcomp/hal/linux/socketcan_socket.hpp"

namespace volcomp::hal::socketcan {
namespace {

std::string Iface() {
  const char* v = std::getenv("VOLCOMP_VCAN");
  return v != nullptr ? v : "vcan0";
}

SocketCanSocket OpenOrFail(const SocketCanSocket::Options& options) {
  SocketCanSocket s;
  const Expected<void> opened = s.Open(Iface(), options);
  EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error().message);
  return s;
}

CanFrame Frame(uint32_t id, uint8_t n) {
  CanFrame f;
  f.id = id;
  f.dlc = 8;
  for (uint8_t i = 0; i < 8; ++i) f.data[i] = static_cast<uint8_t>(n + i);
  return f;
}

// Reads until nothing is waiting; returns the data frames read.
int Drain(SocketCanSocket& s, uint32_t* last_id = nullptr) {
  int n = 0;
  for (;;) {
    CanFrame f;
    CanErrorInfo info;
    bool is_error = false;
    int err = 0;
    if (s.Read(&f, &info, &is_error, &err) != SocketCanSocket::IoResult::kOk) return n;
    if (is_error) continue;
    if (last_id != nullptr) *last_id = f.id;
    ++n;
  }
}

void Send(SocketCanSocket& s, const CanFrame& f) {
  int err = 0;
  while (s.Write(f, &err) == SocketCanSocket::IoResult::kWouldBlock) {
    s.WaitWritable(std::chrono::milliseconds(10));
  }
}

TEST(SocketCanKernel, TheFilterKeepsOtherFramesOutOfTheBuffer) {
  SocketCanSocket::Options only_590;
  only_590.filters.push_back({0x590, 0x7FF, false});
  SocketCanSocket reader = OpenOrFail(only_590);
  SocketCanSocket writer = OpenOrFail({});
  for (uint8_t i = 0; i < 20; ++i) Send(writer, Frame(0x201, i));
  Send(writer, Frame(0x590, 1));
  uint32_t id = 0;
  EXPECT_EQ(Drain(reader, &id), 1);
  EXPECT_EQ(id, 0x590u);
  EXPECT_EQ(reader.dropped_frames(), 0u);
}

TEST(SocketCanKernel, FramesDroppedByAFullBufferAreCounted) {
  SocketCanSocket reader = OpenOrFail({});  // the kernel's default buffer
  SocketCanSocket writer = OpenOrFail({});
  const int sent = 5000;
  for (int i = 0; i < sent; ++i) Send(writer, Frame(0x123, static_cast<uint8_t>(i)));
  int read = Drain(reader);
  // The kernel hands the count over with the next frame queued after the drops (SO_RXQ_OVFL).
  EXPECT_EQ(reader.dropped_frames(), 0u);
  Send(writer, Frame(0x123, 0));
  read += Drain(reader);
  const int sent_in_all = sent + 1;
  std::printf("[ metric ] default receive buffer %u bytes: %d of %d frames read, %u dropped\n",
              reader.receive_buffer_bytes(), read, sent_in_all, reader.dropped_frames());
  EXPECT_GT(reader.dropped_frames(), 0u);
  EXPECT_EQ(static_cast<uint32_t>(read) + reader.dropped_frames(),
            static_cast<uint32_t>(sent_in_all));
}

TEST(SocketCanKernel, AnEnlargedBufferHoldsWhatTheDefaultDrops) {
  SocketCanSocket::Options large;
  large.receive_buffer_bytes = 1u << 20;
  SocketCanSocket reader = OpenOrFail(large);
  SocketCanSocket writer = OpenOrFail({});
  EXPECT_GE(reader.receive_buffer_bytes(), 1u << 20);  // root may force it (the kernel doubles)
  const int sent = 1000;
  for (int i = 0; i < sent; ++i) Send(writer, Frame(0x124, static_cast<uint8_t>(i)));
  EXPECT_EQ(Drain(reader), sent);
  EXPECT_EQ(reader.dropped_frames(), 0u);
}

}  // namespace
}  // namespace volcomp::hal::socketcan
