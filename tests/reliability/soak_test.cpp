// Soak: random trajectories through the simulated board (the real firmware on the mock HAL on the
// simulated CAN bus) with compensation active, table activations attempted during motion (must be
// refused with 0x08000022), and the reference lost (drive alarm) and regained (home switches)
// again and again. Zero lost steps (the drives end exactly at input + applied correction, and the
// planned output equals input + correction - backlog at every tick) and zero pulse-timing
// violations over 10^7 input steps; VOLCOMP_SOAK_STEPS=1000000000 for the long run.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/sdo_client.hpp"
#include "volcomp/sim/simulated_board.hpp"
#include "xyz_image.hpp"

namespace volcomp {
namespace {

using canopen::ObjectId;
using canopen::TableCommand;
using canopen_client::SdoClient;

std::vector<uint8_t> SteepImage(uint32_t id, int seed) {
  std::mt19937 rng(static_cast<uint32_t>(seed));
  std::vector<int16_t> v(5 * 5 * 5 * 3);
  for (auto& x : v) x = static_cast<int16_t>(static_cast<int>(rng() % 8001) - 4000);  // +-250 steps
  return testing::XyzImage(id, 5, -200000, 100000, v);
}

class Soak {
 public:
  Soak() : bus_(1000000) {
    sim::SimulatedBoardOptions o;
    o.write_enable_input = true;
    o.settings.board = DefaultBoardConfig();
    for (int a = 0; a < 3; ++a) {
      AxisConfig& ax = o.settings.board.axis[a];
      ax.max_correction_steps = 300;
      ax.max_correction_rate_steps_s = 20000;
      ax.max_correction_accel_steps_s2 = 4000000;
      ax.max_input_rate_hz = 1000000;
      ax.drive = {200, 200, 300, 300, 2000000};
    }
    board_ = std::make_unique<sim::SimulatedBoard>(bus_, o);
    pc_ = &bus_.Attach("pc");
    EXPECT_TRUE(board_->Start().ok());
  }

  // Advances to `t` in event order, checking the exactness invariant after every tick.
  void AdvanceTo(uint64_t t) {
    sim::AdvanceInEventOrder(bus_, *board_, t);
    const ControlTick& e = board_->app().control_tick();
    const StepOutput& out = board_->output();
    for (uint8_t a = 0; a < 3; ++a) {
      ASSERT_EQ(out.position(a) + out.backlog(a, e.target(a)), input_[a] + e.correction_steps(a));
    }
  }
  canopen_client::SdoExpected<std::vector<uint8_t>> Sdo(ObjectId id, std::vector<uint8_t> data) {
    const canopen::ObjectEntry& e = canopen::Entry(id);
    return Sdo(e.index, e.sub, std::move(data));
  }
  canopen_client::SdoExpected<std::vector<uint8_t>> Command(TableCommand c) {
    return Sdo(ObjectId::kTableControl, {static_cast<uint8_t>(canopen::Value(c))});
  }
  canopen_client::SdoExpected<std::vector<uint8_t>> Sdo(uint16_t index,
                                                        uint8_t sub,
                                                        std::vector<uint8_t> data,
                                                        bool upload = false) {
    SdoClient c(0x10);
    if (upload) {
      c.StartRead(index, sub);
    } else {
      c.StartWrite(index, sub, std::move(data));
    }
    while (!c.done()) {
      CanFrame f;
      while (c.PopTx(&f)) pc_->Send(f);
      AdvanceTo(bus_.now() + 50000);
      Move();
      while (pc_->Receive(&f)) c.OnFrame(f, bus_.now() / 1000);
      c.Poll(bus_.now() / 1000);
    }
    CanFrame f;
    while (c.PopTx(&f)) pc_->Send(f);
    return c.result();
  }
  // One 20 us slice of random motion on every axis (up to 20 steps = 1 MHz), kept in +-250000.
  void Move() {
    for (uint8_t a = 0; a < 3; ++a) {
      if (rng_() % 97 == 0) rate_[a] = static_cast<int>(rng_() % 21);
      if (rng_() % 401 == 0 || (input_[a] > 250000 && dir_[a] > 0) ||
          (input_[a] < -250000 && dir_[a] < 0)) {
        dir_[a] = -dir_[a];
      }
      const int32_t d = stopped_ ? 0 : rate_[a] * dir_[a];
      board_->step_io().add_steps(a, d);
      input_[a] += d;
      steps_ += static_cast<uint64_t>(std::abs(d));
    }
  }

  std::mt19937_64 rng_{31};
  sim::SimBus bus_;
  std::unique_ptr<sim::SimulatedBoard> board_;
  sim::Endpoint* pc_ = nullptr;
  int32_t input_[3] = {};
  int rate_[3] = {10, 5, 15};
  int dir_[3] = {1, -1, 1};
  bool stopped_ = false;
  uint64_t steps_ = 0;
};

TEST(Soak, RandomTrajectoriesActivationsAndReferenceLossWithoutLostSteps) {
  const char* env = std::getenv("VOLCOMP_SOAK_STEPS");
  const uint64_t want = env ? std::strtoull(env, nullptr, 10) : 10000000ull;
  Soak s;
  const std::vector<uint8_t> images[2] = {SteepImage(1, 1), SteepImage(2, 2)};
  uint32_t refused = 0, activated = 0, reference_losses = 0;
  // Stage and activate the first table at rest after referencing.
  auto upload = [&](const std::vector<uint8_t>& img) {
    ASSERT_TRUE(s.Command(TableCommand::kClear).ok());
    ASSERT_TRUE(s.Sdo(ObjectId::kTableData, img).ok());
    ASSERT_TRUE(s.Command(TableCommand::kVerify).ok());
  };
  s.stopped_ = true;
  upload(images[0]);
  ASSERT_TRUE(s.Sdo(ObjectId::kReferenceAxes, {7}).ok());
  s.AdvanceTo(s.bus_.now() + 150000000);
  ASSERT_TRUE(s.Command(TableCommand::kActivate).ok());
  s.stopped_ = false;
  int which = 1;
  uint64_t tick = 0;
  while (s.steps_ < want) {
    s.Move();
    s.AdvanceTo(s.bus_.now() + 20000);
    if (::testing::Test::HasFatalFailure()) return;
    ++tick;
    if (tick % 50000 == 0) {  // stage the other table and try to activate it while moving
      upload(images[which]);
      const auto r = s.Command(TableCommand::kActivate);
      ASSERT_FALSE(r.ok());
      ASSERT_EQ(canopen_client::AbortOf(r), canopen::SdoAbort::kDeviceState);
      ++refused;
    }
    if (tick % 120000 == 0) {  // drive alarm: reference lost, correction ramps out
      s.board_->io().SetInput(hal::InputLine::kDriveAlarm, true);
      for (int i = 0; i < 20000; ++i) {
        s.Move();
        s.AdvanceTo(s.bus_.now() + 20000);
      }
      s.board_->io().SetInput(hal::InputLine::kDriveAlarm, false);
      ++reference_losses;
      for (uint8_t a = 0; a < 3; ++a) s.board_->io().SetInput(hal::HomeLine(a), true);
      s.AdvanceTo(s.bus_.now() + 2000000);
      for (uint8_t a = 0; a < 3; ++a) s.board_->io().SetInput(hal::HomeLine(a), false);
    }
    if (tick % 170000 == 0) {  // stop, activate the staged table at rest, go on
      s.stopped_ = true;
      s.AdvanceTo(s.bus_.now() + 150000000);
      const auto r = s.Command(TableCommand::kActivate);
      ASSERT_TRUE(r.ok()) << r.error().message;
      ++activated;
      which = 1 - which;
      s.stopped_ = false;
    }
  }
  // Settle at rest and compare the drives with input + applied correction.
  s.stopped_ = true;
  s.AdvanceTo(s.bus_.now() + 200000000);
  const ControlTick& e = s.board_->app().control_tick();
  const StepOutput& out = s.board_->output();
  uint64_t violations = 0, output_steps = 0;
  for (uint8_t a = 0; a < 3; ++a) {
    const auto& drive = s.board_->step_io().drive(a);
    EXPECT_EQ(drive.position(), int64_t{s.input_[a]} + e.correction_steps(a)) << int(a);
    for (const auto& v : drive.violation_log()) ADD_FAILURE() << "axis " << int(a) << ": " << v;
    violations += drive.violations();
    output_steps += drive.steps();
    EXPECT_EQ(out.backlog(a, e.target(a)), 0);
  }
  EXPECT_EQ(violations, 0u);
  EXPECT_GT(refused, 0u);
  EXPECT_GT(activated, 0u);
  std::printf(
      "[ metric ] soak: %llu input steps, %llu output steps, %.1f s simulated, %u "
      "activations refused while moving, %u activations at rest, %u reference losses, "
      "0 lost steps, %llu timing violations, max backlog %u steps\n",
      static_cast<unsigned long long>(s.steps_), static_cast<unsigned long long>(output_steps),
      static_cast<double>(s.bus_.now()) * 1e-9, refused, activated, reference_losses,
      static_cast<unsigned long long>(violations),
      std::max({out.max_backlog(0), out.max_backlog(1), out.max_backlog(2)}));
}

}  // namespace
}  // namespace volcomp
