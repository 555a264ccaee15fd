// The board application on the mock HAL for end-to-end tests (board_objects_test.cpp,
// board_thermal_test.cpp): the board with step/dir I/O, a mock CAN bus, flash and clock, driven
// tick by tick with a main-loop pass every millisecond, and the PC tool's SDO client on the bus.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "frames.hpp"
#include "test_tables.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"

namespace volcomp::bench {

using canopen::ObjectId;
using canopen::TableCommand;
using canopen_client::SdoClient;
using TransferResult = canopen_client::SdoExpected<std::vector<uint8_t>>;
using hal::InputLine;

constexpr uint8_t kNode = 0x10;

inline testing::AlignedBytes UniformImage(double cx, uint32_t id, uint32_t resolution_y = 1000000) {
  testing::GridCase g;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {8, -100000, 30000};
  for (size_t i = 0; i < g.count(); i += 3) {
    g.i16.push_back(static_cast<int16_t>(cx * 256));
    g.i16.push_back(0);
    g.i16.push_back(0);
  }
  g.steps.assign(g.i16.size(), 0);
  testing::AlignedBytes img = testing::WriteGridImage(g, id);
  if (resolution_y != 1000000) {
    StoreLe32(img.data() + 24 + 8 + 4 + 8 + 4, resolution_y);
    testing::FixCrc(img);
  }
  return img;
}

class Bench : public ::testing::Test {
 protected:
  Bench()
      : config_(DefaultBoardConfig()),
        io_(&clock_, nullptr),
        tables_(256 * 1024, 2048, 8, &clock_, nullptr),
        settings_(8 * 1024, 2048, 8, &clock_, nullptr),
        can_(&clock_, nullptr, 256),
        step_io_(config_, nullptr),
        tick_io_(&step_io_),
        app_({&tick_io_, &io_, &tables_, &settings_, &can_, &clock_}) {}

  void Boot() {
    BoardSettings s;
    s.board = config_;
    Boot(s);
  }
  void Boot(const BoardSettings& settings) {
    ASSERT_TRUE(app_.Start(settings).ok());
    io_.SetInput(InputLine::kEnable, true);
    Step(100);
    can_.TakeSent();
  }
  // Runs `ticks` 20 us ticks with a main-loop pass every 50 ticks (1 ms).
  void Step(int ticks) {
    for (int i = 0; i < ticks; ++i) {
      step_io_.set_tick_start_ns(clock_.now());
      app_.Tick();
      if (++tick_count_ % 50 == 0) app_.Poll();
      clock_.Advance(20000);
    }
  }
  TransferResult Run(SdoClient& c) {
    while (!c.done()) {
      CanFrame f;
      while (c.PopTx(&f)) can_.Inject(f);
      Step(50);
      for (const CanFrame& r : can_.TakeSent()) {
        sent_.push_back(r);
        c.OnFrame(r, clock_.now() / 1000);
      }
      c.Poll(clock_.now() / 1000);
    }
    CanFrame f;
    while (c.PopTx(&f)) can_.Inject(f);
    Step(50);
    return c.result();
  }
  TransferResult Write(ObjectId id, uint32_t value) {
    SdoClient c(kNode);
    canopen_client::StartNumericWrite(c, id, value);
    return Run(c);
  }
  TransferResult Command(TableCommand c) {
    return Write(ObjectId::kTableControl, canopen::Value(c));
  }
  uint32_t Read(ObjectId id) {
    const auto& e = canopen::Entry(id);
    SdoClient c(kNode);
    c.StartRead(e.index, e.sub);
    const TransferResult r = Run(c);
    EXPECT_TRUE(r.ok()) << r.error().message;
    if (!r.ok()) return 0;
    uint32_t v = 0;
    for (size_t i = 0; i < r->size() && i < 4; ++i) v |= uint32_t{(*r)[i]} << (8 * i);
    return v;
  }
  TransferResult Upload(const testing::AlignedBytes& img) {
    SdoClient c(kNode);
    c.StartWrite(0x2100, 0, std::vector<uint8_t>(img.data(), img.data() + img.size()));
    return Run(c);
  }
  void Home() {
    for (uint8_t a = 0; a < 3; ++a) io_.SetInput(hal::HomeLine(a), true);
    Step(100);
    for (uint8_t a = 0; a < 3; ++a) io_.SetInput(hal::HomeLine(a), false);
    Step(100);
  }
  // The PC tool's view of the board: a blocking frame link over the mock bus (requests to 0x2110
  // are counted).
  canopen_client::FrameLink Link() {
    canopen_client::FrameLink l;
    l.send = [this](const CanFrame& f) {
      if (LoadLe16(f.data + 1) == 0x2110) ++unlock_requests_;
      can_.Inject(f);
      return Outcome::Ok();
    };
    l.receive = [this](uint64_t timeout_us) -> Expected<std::optional<CanFrame>> {
      const uint64_t end = clock_.now() + timeout_us * 1000;
      while (replies_.empty() && clock_.now() < end) {
        Step(50);
        for (const CanFrame& r : can_.TakeSent()) {
          sent_.push_back(r);
          replies_.push_back(r);
        }
      }
      if (replies_.empty()) return std::optional<CanFrame>();
      const CanFrame f = replies_.front();
      replies_.erase(replies_.begin());
      return std::optional<CanFrame>(f);
    };
    l.now_us = [this] { return clock_.now() / 1000; };
    return l;
  }
  // Frame level: injects one SDO request (hex, CiA 301 layout) and returns the board's SDO
  // responses of the next main-loop pass.
  std::vector<std::string> Exchange(const std::string& hex) {
    can_.Inject(testing::F(0x600 + kNode, hex));
    Step(50);
    std::vector<std::string> out;
    for (const CanFrame& f : can_.TakeSent()) {
      sent_.push_back(f);
      if (f.id == 0x580u + kNode) out.push_back(testing::ToString(f));
    }
    return out;
  }
  // An NMT command to this node; returns every frame the board sent in the next 2 ms.
  std::vector<std::string> Nmt(uint8_t command) {
    can_.Inject(CanFrame{0x000, false, false, 2, {command, kNode}});
    Step(100);
    std::vector<std::string> out;
    for (const CanFrame& f : can_.TakeSent()) {
      sent_.push_back(f);
      out.push_back(testing::ToString(f));
    }
    return out;
  }
  int CountEmcy(uint16_t code) const {
    int n = 0;
    for (const CanFrame& f : sent_) {
      canopen::Emcy e;
      if (canopen::DecodeEmcy(f, kNode, &e) && e.code == code) ++n;
    }
    return n;
  }

  BoardConfig config_;
  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockFlash tables_, settings_;
  hal::mock::MockCan can_;
  hal::mock::MockStepIo step_io_;
  firmware::StepDirIo<hal::mock::MockStepIo> tick_io_;
  firmware::BoardApp<firmware::StepDirIo<hal::mock::MockStepIo>> app_;
  std::vector<CanFrame> sent_;
  std::vector<CanFrame> replies_;  // received through Link(), not yet taken
  int unlock_requests_ = 0;
  uint64_t tick_count_ = 0;
};

}  // namespace volcomp::bench
